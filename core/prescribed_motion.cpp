#include "core/prescribed_motion.hpp"

#include <algorithm>
#include <cmath>

namespace tribo {

BodyState PrescribedMotion::at(const Body& body, double t) const {
  BodyState s;
  s.position = body.position +
               Vec3(velocity[0].integral(t), velocity[1].integral(t), velocity[2].integral(t));
  s.velocity = Vec3(velocity[0].value(t), velocity[1].value(t), velocity[2].value(t));
  const double angle = spin_rate.integral(t);
  s.orientation = (Quat(Eigen::AngleAxisd(angle, spin_axis)) * body.orientation).normalized();
  s.angular_velocity = spin_rate.value(t) * spin_axis;
  return s;
}

Vec3 PrescribedMotion::linearAcceleration(double t) const {
  return {velocity[0].derivative(t), velocity[1].derivative(t), velocity[2].derivative(t)};
}

Vec3 PrescribedMotion::angularAcceleration(double t) const {
  return spin_rate.derivative(t) * spin_axis;
}

std::vector<double> PrescribedMotion::breakpoints() const {
  std::vector<double> times = spin_rate.breakpoints();
  for (const Signal& s : velocity) {
    const std::vector<double> b = s.breakpoints();
    times.insert(times.end(), b.begin(), b.end());
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

double PrescribedMotion::speedBound(double duration) const {
  return sampledBound(duration, breakpoints(), [&](double t) {
    return Vec3(velocity[0].value(t), velocity[1].value(t), velocity[2].value(t)).norm();
  });
}

double PrescribedMotion::spinBound(double duration) const {
  return sampledBound(duration, breakpoints(),
                      [&](double t) { return std::abs(spin_rate.value(t)); });
}

void PrescribedMotion::reserveIntegrals(double until) const {
  for (const Signal& s : velocity) s.reserveIntegral(until);
  spin_rate.reserveIntegral(until);
}

std::vector<std::size_t> prescribedBodies(const std::vector<Body>& bodies) {
  std::vector<std::size_t> prescribed;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].motion) prescribed.push_back(b);
  return prescribed;
}

void placePrescribedBodies(const std::vector<Body>& bodies,
                           const std::vector<std::size_t>& prescribed, State& state) {
  for (const std::size_t b : prescribed)
    state.bodies[b] = bodies[b].motion->at(bodies[b], state.time);
}

}  // namespace tribo
