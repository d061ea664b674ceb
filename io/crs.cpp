#include "io/crs.hpp"

#include <proj.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <regex>

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
