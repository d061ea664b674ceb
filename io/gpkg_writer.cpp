#include "io/gpkg_writer.hpp"

#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <mutex>
#include <utility>

#include "io/errors.hpp"
#include "io/temp_registry.hpp"

namespace mc::io {

OGRPolygon to_ogr(const Polygon2& poly) {
  OGRPolygon p;
  for (const Ring2& ring : poly) {
    if (ring.size() < 3) continue;
    OGRLinearRing r;
    for (const auto& pt : ring) r.addPoint(pt[0], pt[1]);
    r.addPoint(ring[0][0], ring[0][1]);
    p.addRing(&r);
  }
  return p;
}

namespace {

void init_gdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    // Reproducible files: gpkg_contents.last_change is otherwise the current time.
    CPLSetConfigOption("OGR_CURRENT_DATE", "2000-01-01T00:00:00.000Z");
    // No rollback journal beside the temp file (an interrupted run leaves only the registered temp).
    CPLSetConfigOption("OGR_SQLITE_JOURNAL", "MEMORY");
  });
}

OGRMultiPolygon to_ogr(const MultiPolygon2& mp) {
  OGRMultiPolygon out;
  for (const Polygon2& poly : mp) {
    OGRPolygon p = mc::io::to_ogr(poly);
    if (!p.IsEmpty()) out.addGeometry(&p);
  }
  return out;
}

OGRFieldType ogr_type(GpkgType t) {
  switch (t) {
    case GpkgType::Integer:
      return OFTInteger64;
    case GpkgType::Real:
      return OFTReal;
    default:
      return OFTString;
  }
}

}  // namespace

struct GpkgWriter::Impl {
  std::string temp;
  int slot = -1;
  GDALDataset* ds = nullptr;
  OGRLayer* buildings = nullptr;
  OGRLayer* parts = nullptr;
  size_t n_columns = 0;
  bool committed = false;

  ~Impl() {
    if (ds) GDALClose(ds);
    if (!committed) std::remove(temp.c_str());
    unregister_temp_file(slot);
  }

  void create(OGRLayer* layer, const char* name, OGRFieldType type) {
    OGRFieldDefn def(name, type);
    if (layer->CreateField(&def) != OGRERR_NONE) throw WriteError(temp + ": cannot create field " + name);
  }
};

GpkgWriter::GpkgWriter(const std::string& path, const std::string& crs, std::vector<GpkgColumn> columns)
    : path_(path), impl_(std::make_unique<Impl>()) {
  init_gdal();
  namespace fs = std::filesystem;
  impl_->temp = fs::absolute(fs::path(path)).string() + ".tmp." + std::to_string(::getpid()) + ".gpkg";
  impl_->slot = register_temp_file(impl_->temp.c_str());
  std::remove(impl_->temp.c_str());
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GPKG");
  if (!drv) throw WriteError(path + ": GDAL has no GPKG driver");
  impl_->ds = drv->Create(impl_->temp.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  if (!impl_->ds) throw WriteError(path + ": cannot create GeoPackage (" + CPLGetLastErrorMsg() + ")");

  OGRSpatialReference srs;
  bool have_srs = false;
  if (!crs.empty()) {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    have_srs = srs.SetFromUserInput(crs.c_str()) == OGRERR_NONE;
    CPLPopErrorHandler();
    if (have_srs && srs.IsCompound()) srs.StripVertical();  // 2D footprints: the horizontal CRS
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  }
  impl_->buildings = impl_->ds->CreateLayer("buildings", have_srs ? &srs : nullptr, wkbMultiPolygon, nullptr);
  impl_->parts = impl_->ds->CreateLayer("parts", have_srs ? &srs : nullptr, wkbMultiPolygon, nullptr);
  if (!impl_->buildings || !impl_->parts) throw WriteError(path + ": cannot create layers");
  for (const auto& c : columns) impl_->create(impl_->buildings, c.name.c_str(), ogr_type(c.type));
  impl_->n_columns = columns.size();
  // The parts layer's columns, in the order of their indices in add_part.
  static const std::pair<const char*, OGRFieldType> kPartColumns[] = {
      {"building", OFTString},     {"part", OFTString},      {"level", OFTReal},
      {"part_index", OFTInteger},  {"role", OFTString},      {"z_min", OFTReal},
      {"z_max", OFTReal},          {"volume", OFTReal},      {"convexity", OFTReal},
      {"footprint_area", OFTReal}, {"grounded", OFTInteger}, {"mass", OFTInteger},
      {"piece", OFTString}};
  for (const auto& [name, type] : kPartColumns) impl_->create(impl_->parts, name, type);
  if (impl_->ds->StartTransaction() != OGRERR_NONE) throw WriteError(path + ": cannot start a transaction");
}

GpkgWriter::~GpkgWriter() = default;

void GpkgWriter::add_building(const MultiPolygon2& footprint, const std::vector<GpkgValue>& values) {
  OGRFeature* f = OGRFeature::CreateFeature(impl_->buildings->GetLayerDefn());
  for (size_t i = 0; i < values.size() && i < impl_->n_columns; ++i) {
    const GpkgValue& v = values[i];
    const int k = static_cast<int>(i);
    if (v.text) f->SetField(k, v.text->c_str());
    else if (v.integer) f->SetField(k, static_cast<GIntBig>(*v.integer));
    else if (v.real) f->SetField(k, *v.real);
    else f->SetFieldNull(k);
  }
  if (!footprint.empty()) {
    OGRMultiPolygon g = to_ogr(footprint);
    f->SetGeometry(&g);
  }
  const OGRErr err = impl_->buildings->CreateFeature(f);
  OGRFeature::DestroyFeature(f);
  if (err != OGRERR_NONE)
    throw WriteError(path_ + ": cannot write a building (" + CPLGetLastErrorMsg() + ")");
}

void GpkgWriter::add_part(const GpkgPart& p) {
  OGRFeature* f = OGRFeature::CreateFeature(impl_->parts->GetLayerDefn());
  f->SetField(0, p.building.c_str());
  f->SetField(1, p.id.c_str());
  f->SetField(2, p.level);
  f->SetField(3, p.index);
  f->SetField(4, p.role.c_str());
  f->SetField(5, p.z_min);
  f->SetField(6, p.z_max);
  f->SetField(7, p.volume);
  f->SetField(8, p.convexity);
  f->SetField(9, p.footprint_area);
  f->SetField(10, p.grounded ? 1 : 0);
  f->SetField(11, p.mass);
  f->SetField(12, p.piece.c_str());
  if (!p.footprint.empty()) {
    OGRMultiPolygon g = to_ogr(p.footprint);
    f->SetGeometry(&g);
  }
  const OGRErr err = impl_->parts->CreateFeature(f);
  OGRFeature::DestroyFeature(f);
  if (err != OGRERR_NONE) throw WriteError(path_ + ": cannot write a part (" + CPLGetLastErrorMsg() + ")");
}

void GpkgWriter::commit() {
  if (impl_->ds->CommitTransaction() != OGRERR_NONE)
    throw WriteError(path_ + ": cannot commit the GeoPackage");
  GDALDataset* ds = impl_->ds;
  impl_->ds = nullptr;
  GDALClose(ds);
  if (std::rename(impl_->temp.c_str(), path_.c_str()) != 0)
    throw WriteError(path_ + ": cannot rename the GeoPackage into place");
  impl_->committed = true;
}

}  // namespace mc::io
