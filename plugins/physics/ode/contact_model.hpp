// Contacts: what happens when two geoms touch. ODE finds the contact points of a pair
// (dCollide); this turns each into a contact joint with Coulomb friction and soft ERP/CFM.
//
// Every contact is made planar before it becomes a joint: its point is put on z = 0 and its
// normal in the plane, and friction acts only along the in-plane tangent (mu2 = 0 for the
// vertical direction). Forces then never tilt or lift a body, so the bodies stay exactly in the
// plane without a plane joint.
#pragma once

#include <ode/ode.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ode_parameters.hpp"

namespace swarmnet::ode {

class ContactModel {
 public:
  explicit ContactModel(const OdeParameters& parameters);

  // Call before dSpaceCollide with this model as its data. `touching` (one flag per robot,
  // cleared here) receives 1 for every robot that gets a contact: robots are the bodies whose
  // data is their index + 1 (robot_drive.hpp).
  void begin(dWorldID world, dJointGroupID group, std::vector<std::uint8_t>* touching) {
    world_ = world;
    group_ = group;
    count_ = 0;
    touching_ = touching;
    if (touching_ != nullptr) std::fill(touching_->begin(), touching_->end(), 0);
  }
  [[nodiscard]] std::size_t last_count() const { return count_; }

  // dNearCallback: `data` is the ContactModel.
  static void near_callback(void* data, dGeomID a, dGeomID b);

  // Most contact points kept per pair: a sphere touches anything at one point, a box a box at up
  // to four.
  static constexpr int kMaxContactsPerPair = 4;

 private:
  void collide(dGeomID a, dGeomID b);
  void mark(dBodyID body);

  double friction_;
  double erp_;
  double cfm_;
  dWorldID world_ = nullptr;
  dJointGroupID group_ = nullptr;
  std::size_t count_ = 0;
  std::vector<std::uint8_t>* touching_ = nullptr;
};

}  // namespace swarmnet::ode
