#include "io/crs.hpp"

#include <proj.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <mutex>
#include <regex>
#include <vector>

namespace mc::io {

std::string normalize_crs(const std::string& crs) {
  // .../def/crs/EPSG/<version>/<code>  and  urn:ogc:def:crs:EPSG:<version?>:<code>
  static const std::regex url(R"(^https?://www\.opengis\.net/def/crs/epsg/[0-9.]+/([0-9]+)/?$)",
                              std::regex::icase);
  static const std::regex urn(R"(^urn:ogc:def:crs:epsg:[0-9.]*:([0-9]+)$)", std::regex::icase);
  static const std::regex plain(R"(^epsg:([0-9]+)$)", std::regex::icase);
  std::smatch m;
  if (std::regex_match(crs, m, url) || std::regex_match(crs, m, urn) || std::regex_match(crs, m, plain))
    return "EPSG:" + m[1].str();
  return crs;
}

namespace {

// A PROJ object freed at the end of its scope.
struct Pj {
  PJ* p = nullptr;
  explicit Pj(PJ* q) : p(q) {}
  ~Pj() {
    if (p) proj_destroy(p);
  }
  Pj(const Pj&) = delete;
  Pj& operator=(const Pj&) = delete;
};

struct Axis {
  std::string direction;
  double unit = 1;  // metres (or radians) per unit
};

std::vector<Axis> axes_of(PJ_CONTEXT* ctx, const PJ* crs) {
  std::vector<Axis> out;
  const Pj cs(proj_crs_get_coordinate_system(ctx, crs));
  if (!cs.p) return out;
  for (int i = 0, n = proj_cs_get_axis_count(ctx, cs.p); i < n; ++i) {
    const char* direction = nullptr;
    double factor = 1;
    if (proj_cs_get_axis_info(ctx, cs.p, i, nullptr, nullptr, &direction, &factor, nullptr, nullptr, nullptr))
      out.push_back({direction ? direction : "", factor});
  }
  return out;
}

}  // namespace

CoordinateSystem coordinate_system(const std::string& crs, bool axis_order_of_crs, std::string* note) {
  CoordinateSystem cs;
  if (crs.empty()) return cs;
  auto say = [&](const std::string& s) {
    if (note) *note = s;
  };
  std::unique_ptr<PJ_CONTEXT, PJ_CONTEXT* (*)(PJ_CONTEXT*)> ctx(proj_context_create(), &proj_context_destroy);
  if (!ctx) return cs;
  proj_context_set_enable_network(ctx.get(), 0);
  proj_log_level(ctx.get(), PJ_LOG_NONE);
  const Pj whole(proj_create(ctx.get(), normalize_crs(crs).c_str()));
  if (!whole.p) {
    say("CRS '" + crs + "' is not known to PROJ: coordinates are taken as metres");
    return cs;
  }
  Pj horizontal(nullptr), vertical(nullptr);
  const PJ* h = whole.p;
  if (proj_get_type(whole.p) == PJ_TYPE_COMPOUND_CRS) {
    horizontal.p = proj_crs_get_sub_crs(ctx.get(), whole.p, 0);
    vertical.p = proj_crs_get_sub_crs(ctx.get(), whole.p, 1);
    h = horizontal.p;
  }
  if (!h) return cs;
  if (proj_get_type(h) == PJ_TYPE_BOUND_CRS) {  // a CRS with its towgs84: the CRS itself counts
    horizontal.p = proj_get_source_crs(ctx.get(), h);
    h = horizontal.p;
    if (!h) return cs;
  }
  const PJ_TYPE type = proj_get_type(h);
  const std::vector<Axis> axes = axes_of(ctx.get(), h);
  if (type == PJ_TYPE_GEOCENTRIC_CRS) {
    cs.kind = CoordinateSystem::Kind::Geocentric;
    return cs;
  }
  if (type == PJ_TYPE_GEOGRAPHIC_2D_CRS || type == PJ_TYPE_GEOGRAPHIC_3D_CRS) {
    cs.kind = CoordinateSystem::Kind::Geographic;
    cs.lat_first =
        axis_order_of_crs && !axes.empty() && (axes[0].direction == "north" || axes[0].direction == "south");
    constexpr double kDegree = M_PI / 180;
    if (!axes.empty() && std::abs(axes[0].unit / kDegree - 1) > 1e-9)
      say("CRS '" + crs + "' has angular units other than degrees; they are read as degrees");
    if (axes.size() >= 3) cs.vertical_unit = axes[2].unit;
  } else {
    if (!axes.empty() && axes[0].unit > 0 && axes[0].unit != 1) {
      cs.kind = CoordinateSystem::Kind::Scaled;
      cs.horizontal_unit = axes[0].unit;
    }
    if (axes.size() >= 3 && axes[2].unit > 0) cs.vertical_unit = axes[2].unit;
  }
  if (vertical.p) {
    const std::vector<Axis> v = axes_of(ctx.get(), vertical.p);
    if (!v.empty() && v[0].unit > 0) cs.vertical_unit = v[0].unit;
  } else if (type != PJ_TYPE_GEOGRAPHIC_3D_CRS && axes.size() < 3 &&
             cs.kind == CoordinateSystem::Kind::Scaled) {
    cs.vertical_unit = cs.horizontal_unit;  // a 2D CRS in feet: heights in the same unit
  }
  return cs;
}

struct CrsTransformer::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* op = nullptr;
  std::string error;
  std::mutex mutex;

  ~Impl() {
    if (op) proj_destroy(op);
    if (ctx) proj_context_destroy(ctx);
  }

  void fail(const std::string& what) {
    const int err = proj_context_errno(ctx);
    error = what;
    if (err) error += std::string(": ") + proj_context_errno_string(ctx, err);
  }

  void build(const std::string& crs) {
    ctx = proj_context_create();
    if (!ctx) {
      error = "cannot create a PROJ context";
      return;
    }
    proj_context_set_enable_network(ctx, 0);  // never fetch grids: deterministic and offline
    proj_log_level(ctx, PJ_LOG_NONE);         // errors are reported through error()
    const std::string id = normalize_crs(crs);
    PJ* src = proj_create(ctx, id.c_str());
    if (!src) return fail("unknown CRS '" + crs + "'");
    if (proj_get_type(src) == PJ_TYPE_COMPOUND_CRS) {
      PJ* horizontal = proj_crs_get_sub_crs(ctx, src, 0);
      proj_destroy(src);
      src = horizontal;
      if (!src) return fail("cannot take the horizontal part of '" + crs + "'");
    }
    PJ* dst = proj_create(ctx, "EPSG:4326");
    if (!dst) {
      proj_destroy(src);
      return fail("cannot create EPSG:4326");
    }
    PJ* raw = proj_create_crs_to_crs_from_pj(ctx, src, dst, nullptr, nullptr);
    proj_destroy(src);
    proj_destroy(dst);
    if (!raw) return fail("no transformation from '" + crs + "' to WGS84");
    op = proj_normalize_for_visualization(ctx, raw);  // lon, lat order whatever EPSG says
    proj_destroy(raw);
    if (!op) fail("cannot normalise the axis order of '" + crs + "'");
  }
};

CrsTransformer::CrsTransformer(const std::string& crs) : impl_(std::make_unique<Impl>()) {
  if (crs.empty()) {
    impl_->error = "no CRS";
    return;
  }
  impl_->build(crs);
}

CrsTransformer::~CrsTransformer() = default;
CrsTransformer::CrsTransformer(CrsTransformer&&) noexcept = default;
CrsTransformer& CrsTransformer::operator=(CrsTransformer&&) noexcept = default;

bool CrsTransformer::valid() const { return impl_ && impl_->op; }

const std::string& CrsTransformer::error() const {
  static const std::string moved = "moved-from CrsTransformer";
  return impl_ ? impl_->error : moved;
}

std::optional<std::pair<double, double>> CrsTransformer::to_lonlat(double x, double y, double z) const {
  if (!valid() || !std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  std::lock_guard lock(impl_->mutex);
  // Heights are ignored: the operation is horizontal, and a grid-free Helmert would otherwise
  // shift lon/lat by micro-degrees with z, so equal x/y would not give byte-equal CSV cells.
  (void)z;
  PJ_COORD c = proj_coord(x, y, 0, 0);
  proj_errno_reset(impl_->op);
  const PJ_COORD r = proj_trans(impl_->op, PJ_FWD, c);
  const double lon = r.lpzt.lam, lat = r.lpzt.phi;
  if (proj_errno(impl_->op) != 0 || !std::isfinite(lon) || !std::isfinite(lat) || std::abs(lat) > 90 ||
      std::abs(lon) > 360)
    return std::nullopt;
  return std::make_pair(lon, lat);
}

}  // namespace mc::io
