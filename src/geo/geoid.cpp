// The EGM96 geoid through PROJ. PROJ's vgridshift adds multiplier x grid value to the height in
// the forward direction; with multiplier 1 and a height of 0 the result is the grid value itself,
// the undulation N, so the sign convention is ours (h = H + N) and not a PROJ default.
#include <unistd.h>

#include <cmath>
#include <mutex>
#include <sstream>

#include <proj.h>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::geo {

namespace {
constexpr const char* kEgm96Grid = "egm96_15.gtx";  // proj-data, /usr/share/proj

// The grid's absolute path in PROJ's search path (PROJ_DATA, the user's and the system's data
// directories, in PROJ's order); empty when it is in none of them.
std::string find_in_search_path(const std::string& grid) {
  std::istringstream directories(proj_info().searchpath);
  for (std::string directory; std::getline(directories, directory, ':');) {
    const std::string path = directory + "/" + grid;
    if (!directory.empty() && access(path.c_str(), R_OK) == 0) return path;
  }
  return {};
}

// PROJ 9.1 opens its database proj.db in every proj_create, whatever the text (later versions
// only when the text needs it); its SQLite cache is ~3 MB of the driver's resident memory and the
// geoid's pipeline needs nothing from it. Given the grid's absolute path, PROJ looks nothing up;
// the context's only search path is then the grid file itself, under which no proj.db can be
// found. A grid outside the search path keeps PROJ's own lookup (the database's grid
// alternatives, the network when enabled).
std::string grid_without_database(PJ_CONTEXT* context, const std::string& grid) {
  const std::string path = find_in_search_path(grid);
  if (path.empty()) return grid;
  const char* search_paths[] = {path.c_str()};
  proj_context_set_search_paths(context, 1, search_paths);
  return path;
}

}  // namespace

struct Geoid::Impl {
  mutable std::mutex mutex;  // a PROJ context is not for two threads at once
  PJ_CONTEXT* context = nullptr;
  PJ* transform = nullptr;
  std::string error;  // why the geoid is unusable; empty when it is
};

Geoid::Geoid(const char* grid) : impl_(std::make_unique<Impl>()) {
  impl_->context = proj_context_create();
  if (!impl_->context) {
    impl_->error = "PROJ: cannot create a context";
    return;
  }
  // Failures are reported through Result. PROJ 9.1 writes "Cannot find proj.db" even at
  // PJ_LOG_NONE (grid_without_database() hides it on purpose): no logger at all.
  proj_log_level(impl_->context, PJ_LOG_NONE);
  proj_log_func(impl_->context, nullptr, [](void*, int, const char*) {});
  const std::string pipeline =
      std::string("+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad ") +
      "+step +proj=vgridshift +multiplier=1 +grids=" + grid_without_database(impl_->context, grid);
  impl_->transform = proj_create(impl_->context, pipeline.c_str());
  if (!impl_->transform) {
    impl_->error = std::string("PROJ cannot load the geoid grid ") + grid +
                   " (package proj-data): " +
                   proj_context_errno_string(impl_->context, proj_context_errno(impl_->context));
  }
}

Geoid::~Geoid() {
  if (impl_->transform) proj_destroy(impl_->transform);
  if (impl_->context) proj_context_destroy(impl_->context);
}

const Geoid& Geoid::egm96() {
  static const Geoid geoid(kEgm96Grid);
  return geoid;
}

Result<double> Geoid::undulation_m(double latitude_deg, double longitude_deg) const {
  if (!impl_->error.empty()) return Result<double>::fail(impl_->error);
  const Status valid = check_geodetic({latitude_deg, longitude_deg, 0});
  if (!valid) return Result<double>::fail(valid.message());
  // The grid covers longitudes -180..180.
  const double longitude = std::remainder(longitude_deg, 360.0);
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const PJ_COORD in = proj_coord(longitude, latitude_deg, 0.0, 0.0);
  const PJ_COORD out = proj_trans(impl_->transform, PJ_FWD, in);
  if (!std::isfinite(out.xyz.z) || out.xyz.z == HUGE_VAL) {
    const int error = proj_errno(impl_->transform);
    proj_errno_reset(impl_->transform);
    return Result<double>::fail(std::string("PROJ: no geoid height at that position: ") +
                                proj_context_errno_string(impl_->context, error));
  }
  return out.xyz.z;
}

Result<double> Geoid::msl_from_ellipsoid(double latitude_deg, double longitude_deg,
                                         double height_ellipsoid_m) const {
  const Result<double> n = undulation_m(latitude_deg, longitude_deg);
  if (!n) return n;
  return height_ellipsoid_m - n.value();
}

Result<double> Geoid::ellipsoid_from_msl(double latitude_deg, double longitude_deg,
                                         double height_msl_m) const {
  const Result<double> n = undulation_m(latitude_deg, longitude_deg);
  if (!n) return n;
  return height_msl_m + n.value();
}

}  // namespace k40t::geo
