#include "flight/geoid.h"

#include <proj.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace skylit::flight {
namespace {

constexpr const char* kSourceCrs = "EPSG:4979";       // WGS 84, ellipsoidal height
constexpr const char* kTargetCrs = "EPSG:4326+5773";  // WGS 84 + EGM96 height
constexpr const char* kGrid = "egm96_15.gtx";

}  // namespace

struct EllipsoidToGeoid::Proj {
  PJ_CONTEXT* ctx = nullptr;
  PJ* op = nullptr;
  ~Proj() {
    if (op) proj_destroy(op);
    if (ctx) proj_context_destroy(ctx);
  }
};

EllipsoidToGeoid::EllipsoidToGeoid() : proj_(std::make_unique<Proj>()) {
  Proj& p = *proj_;
  p.ctx = proj_context_create();
  proj_log_level(p.ctx, PJ_LOG_NONE);
  const std::string missing = std::string("PROJ cannot use the EGM96 geoid grid ") + kGrid +
                              " for " + kSourceCrs + " -> " + kTargetCrs + " (is proj-data installed?)";
  PJ* src = proj_create(p.ctx, kSourceCrs);
  PJ* dst = proj_create(p.ctx, kTargetCrs);
  PJ_OPERATION_FACTORY_CONTEXT* factory = proj_create_operation_factory_context(p.ctx, nullptr);
  PJ_OBJ_LIST* ops = nullptr;
  if (src && dst && factory) {
    proj_operation_factory_context_set_grid_availability_use(p.ctx, factory,
                                                             PROJ_GRID_AVAILABILITY_DISCARD_OPERATION_IF_MISSING_GRID);
    proj_operation_factory_context_set_allow_ballpark_transformations(p.ctx, factory, 0);
    ops = proj_create_operations(p.ctx, src, dst, factory);
  }
  PJ* chosen = nullptr;
  for (int k = 0; ops && k < proj_list_get_count(ops) && !chosen; ++k) {
    PJ* op = proj_list_get(p.ctx, ops, k);
    if (op && proj_coordoperation_get_grid_used_count(p.ctx, op) > 0 && proj_coordoperation_is_instantiable(p.ctx, op))
      chosen = op;
    else if (op)
      proj_destroy(op);
  }
  if (ops) proj_list_destroy(ops);
  if (factory) proj_operation_factory_context_destroy(factory);
  if (src) proj_destroy(src);
  if (dst) proj_destroy(dst);
  if (!chosen) throw std::runtime_error(missing);
  // Longitude, latitude order in degrees, whatever the CRS axis order.
  p.op = proj_normalize_for_visualization(p.ctx, chosen);
  proj_destroy(chosen);
  if (!p.op) throw std::runtime_error(missing);
}

EllipsoidToGeoid::~EllipsoidToGeoid() = default;

double EllipsoidToGeoid::msl_height(double lat_deg, double lon_deg, double ellipsoidal_m) const {
  const PJ_COORD out = proj_trans(proj_->op, PJ_FWD, proj_coord(lon_deg, lat_deg, ellipsoidal_m, HUGE_VAL));
  if (!std::isfinite(out.xyz.z) || out.xyz.z == HUGE_VAL)
    throw std::runtime_error("PROJ could not convert the ellipsoidal height at lat " + std::to_string(lat_deg) +
                             ", lon " + std::to_string(lon_deg) + " to EGM96");
  return out.xyz.z;
}

}  // namespace skylit::flight
