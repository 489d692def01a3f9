#include "ode_world.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace swarmnet::ode {

namespace {

std::mutex library_mutex;
int library_users = 0;

// QuickStep reorders constraints with ODE's own generator, whose state is global to the library.
// Re-seeding it before every sub-step makes each sub-step a function of the world's state alone,
// whatever else ran in the process before.
constexpr unsigned long kSolverSeed = 0x5eed;

}  // namespace

OdeLibrary::OdeLibrary() {
  const std::lock_guard<std::mutex> lock(library_mutex);
  if (library_users++ == 0) dInitODE2(0);
}

OdeLibrary::~OdeLibrary() {
  const std::lock_guard<std::mutex> lock(library_mutex);
  if (--library_users == 0) dCloseODE();
}

OdeWorld::OdeWorld(const OdeParameters& parameters, const Arena& arena, double typical_radius_m)
    : contacts_(parameters) {
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0.0, 0.0, 0.0);
  dWorldSetERP(world_, parameters.contact_erp);
  dWorldSetCFM(world_, parameters.contact_cfm_m_per_n);
  dWorldSetContactSurfaceLayer(world_, parameters.contact_surface_layer_m);
  dWorldSetQuickStepNumIterations(world_, parameters.solver_iterations);
  dWorldSetAutoDisableFlag(world_, 0);
  // A quad-tree space over the arena (and its walls) keeps collision detection linear in the
  // number of geoms: a geom lives in the smallest block that contains it and is tested only
  // against geoms in its block, its sub-blocks and the blocks above it. Leaves about twelve robot
  // diameters wide (1 to 2 m for foot-bots) measured best from 400 to 10,000 robots; the depth is
  // capped at 8 (87,381 blocks). A hash space was slower at every size (it re-hashes every geom
  // at every level each step) and its cost per geom grew with N; sweep-and-prune measured within
  // 10 % of the quad-tree. ODE's extents are half-sizes.
  const double side_m = std::max({arena.width_m, arena.height_m}) + 2.0 * kWallThicknessM;
  const double leaf_m = 24.0 * typical_radius_m;
  const int depth = std::clamp(static_cast<int>(std::lround(std::log2(side_m / leaf_m))), 1, 8);
  const dVector3 centre = {0.5 * arena.width_m, 0.5 * arena.height_m, 0.0};
  const dVector3 extents = {0.5 * arena.width_m + kWallThicknessM,
                            0.5 * arena.height_m + kWallThicknessM, kStaticHeightM};
  space_ = dQuadTreeSpaceCreate(nullptr, centre, extents, depth);
  contact_group_ = dJointGroupCreate(0);
}

OdeWorld::~OdeWorld() {
  dJointGroupDestroy(contact_group_);
  dSpaceDestroy(space_);  // destroys its geoms too (cleanup mode)
  dWorldDestroy(world_);  // and every body and joint
}

void OdeWorld::add_static_box(double x_min, double y_min, double x_max, double y_max) {
  const dGeomID box = dCreateBox(space_, x_max - x_min, y_max - y_min, kStaticHeightM);
  dGeomSetPosition(box, 0.5 * (x_min + x_max), 0.5 * (y_min + y_max), 0.0);
}

void OdeWorld::add_static_geometry(const Arena& arena) {
  const double w = arena.width_m;
  const double h = arena.height_m;
  const double t = kWallThicknessM;
  add_static_box(-t, -t, w + t, 0.0);   // south
  add_static_box(-t, h, w + t, h + t);  // north
  add_static_box(-t, 0.0, 0.0, h);      // west
  add_static_box(w, 0.0, w + t, h);     // east
  for (const Rect& obstacle : arena.obstacles) {
    add_static_box(obstacle.x_min_m, obstacle.y_min_m, obstacle.x_max_m, obstacle.y_max_m);
  }
}

void OdeWorld::collide(std::vector<std::uint8_t>* touching) {
  contacts_.begin(world_, contact_group_, touching);
  dSpaceCollide(space_, &contacts_, &ContactModel::near_callback);
}

void OdeWorld::advance(double h_s) {
  dRandSetSeed(kSolverSeed);
  dWorldQuickStep(world_, h_s);
  dJointGroupEmpty(contact_group_);
}

}  // namespace swarmnet::ode
