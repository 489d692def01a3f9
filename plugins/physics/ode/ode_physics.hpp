// ode: robots as rigid bodies with mass, inertia and friction in ODE (the Open Dynamics Engine),
// behind the same Physics interface as kinematic2d.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "movable_objects.hpp"
#include "ode_parameters.hpp"
#include "ode_world.hpp"
#include "proximity_sensor.hpp"
#include "robot_drive.hpp"
#include "swarmnet/physics.hpp"

namespace swarmnet::ode {

class OdePhysics final : public Physics {
 public:
  static PluginInfo info();
  explicit OdePhysics(const PluginArgs& args);

  void setup(const Arena& arena, std::span<const RobotBody> bodies) override;
  void step(double dt_s, std::span<RobotBody> bodies) override;
  void sense_proximity(std::span<const RobotBody> bodies, std::size_t robot, double range_m,
                       std::span<double> rays) const override;
  [[nodiscard]] std::span<const ObjectPose> object_poses() const override {
    return objects_.poses();
  }

  // Sub-steps the next step of dt_s would take for `bodies`' commanded wheel speeds: enough that
  // each is at most max_substep_s long and no body, at the larger of its current speed and its
  // fastest commanded wheel speed, moves more than max_travel_fraction of the smallest robot
  // radius or half the smallest object extent.
  [[nodiscard]] int substeps_for(double dt_s, std::span<const RobotBody> bodies) const;
  // Sub-steps the last step() took, and contacts in its last sub-step.
  [[nodiscard]] int last_substeps() const { return last_substeps_; }
  [[nodiscard]] std::size_t last_contact_count() const { return world_->last_contact_count(); }
  // Planar velocity of robot `robot`'s centre, m/s.
  [[nodiscard]] Vec2 velocity(std::size_t robot) const;

  // The sub-step count is capped at this: only a body moving at an absurd speed (a diverged
  // solver) would ask for more, and the step then takes this many rather than stall the run.
  static constexpr int kMaxSubsteps = 100000;

 private:
  OdeParameters parameters_;
  std::unique_ptr<OdeWorld> world_;
  std::vector<RobotDrive> drives_;
  std::vector<std::uint8_t> touching_;  // per robot: has a contact in the current sub-step
  MovableObjects objects_;
  double min_radius_m_ = 0.0;
  ProximitySensor proximity_;
  int last_substeps_ = 0;
};

}  // namespace swarmnet::ode
