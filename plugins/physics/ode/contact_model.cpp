#include "contact_model.hpp"

#include <array>
#include <cmath>

namespace swarmnet::ode {

ContactModel::ContactModel(const OdeParameters& parameters)
    : friction_(parameters.contact_friction),
      erp_(parameters.contact_erp),
      cfm_(parameters.contact_cfm_m_per_n) {}

void ContactModel::near_callback(void* data, dGeomID a, dGeomID b) {
  static_cast<ContactModel*>(data)->collide(a, b);
}

void ContactModel::mark(dBodyID body) {
  if (body == nullptr) return;
  const auto tag = reinterpret_cast<std::uintptr_t>(dBodyGetData(body));
  if (tag > 0 && tag <= touching_->size()) (*touching_)[tag - 1] = 1;
}

void ContactModel::collide(dGeomID a, dGeomID b) {
  const dBodyID body_a = dGeomGetBody(a);
  const dBodyID body_b = dGeomGetBody(b);
  if (body_a == nullptr && body_b == nullptr) return;  // two pieces of static geometry
  std::array<dContact, kMaxContactsPerPair> contacts{};
  const int found = dCollide(a, b, kMaxContactsPerPair, &contacts[0].geom, sizeof(dContact));
  if (found > 0 && touching_ != nullptr) mark(body_a), mark(body_b);
  for (int i = 0; i < found; ++i) {
    dContact& contact = contacts[static_cast<std::size_t>(i)];
    dContactGeom& geom = contact.geom;
    const double nx = geom.normal[0];
    const double ny = geom.normal[1];
    const double length = std::sqrt(nx * nx + ny * ny);
    if (!(length > 0.0)) continue;  // a purely vertical normal cannot occur in the plane
    geom.normal[0] = nx / length;
    geom.normal[1] = ny / length;
    geom.normal[2] = 0.0;
    geom.pos[2] = 0.0;
    contact.surface.mode =
        dContactFDir1 | dContactMu2 | dContactSoftERP | dContactSoftCFM | dContactApprox1;
    contact.surface.mu = friction_;
    contact.surface.mu2 = 0.0;
    contact.surface.soft_erp = erp_;
    contact.surface.soft_cfm = cfm_;
    contact.fdir1[0] = -geom.normal[1];
    contact.fdir1[1] = geom.normal[0];
    contact.fdir1[2] = 0.0;
    const dJointID joint = dJointCreateContact(world_, group_, &contact);
    dJointAttach(joint, body_a, body_b);
    ++count_;
  }
}

}  // namespace swarmnet::ode
