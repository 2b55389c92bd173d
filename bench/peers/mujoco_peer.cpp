// MuJoCo's runs of bench/peers (peer_engines.hpp): the PeerScene written as MJCF (fixed bodies'
// shapes as world geoms, each dynamic body a free body with the scene's mass and principal
// inertia), loaded from a temporary file, stepped with mj_step. Friction: a pair takes the
// larger of its geoms' coefficients (MuJoCo's rule), so every geom gets mu.
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "peer_engines.hpp"

namespace tribo::peers {

namespace {

std::string vec(const Eigen::Vector3d& v) {
  char s[128];
  std::snprintf(s, sizeof s, "%.17g %.17g %.17g", v.x(), v.y(), v.z());
  return s;
}
std::string quat(const Eigen::Quaterniond& q) {
  char s[160];
  std::snprintf(s, sizeof s, "%.17g %.17g %.17g %.17g", q.w(), q.x(), q.y(), q.z());
  return s;
}

std::string header(double dt, const Eigen::Vector3d& gravity, double mu, long ncon,
                   const std::string& solver) {
  std::ostringstream x;
  x << "<mujoco model=\"tribo_peer\">\n"
    << "  <compiler angle=\"radian\"/>\n"
    << "  <option timestep=\"" << dt << "\" gravity=\"" << vec(gravity)
    << "\" integrator=\"Euler\" solver=\"" << solver << "\"/>\n"
    << "  <size nconmax=\"" << ncon << "\" njmax=\"" << 4 * ncon << "\"/>\n"
    << "  <default><geom condim=\"3\" friction=\"" << mu << " 0.005 0.0001\"/></default>\n"
    << "  <worldbody>\n";
  return x.str();
}

std::string geom(const PeerShape& s, const Eigen::Isometry3d& pose) {
  std::ostringstream x;
  x << "<geom pos=\"" << vec(pose.translation()) << "\" quat=\""
    << quat(Eigen::Quaterniond(pose.linear())) << "\" ";
  switch (s.kind) {
    case PeerShape::Kind::kBox:
      x << "type=\"box\" size=\"" << vec(s.half_extents) << "\"/>";
      break;
    case PeerShape::Kind::kSphere:
      x << "type=\"sphere\" size=\"" << s.radius << "\"/>";
      break;
    case PeerShape::Kind::kHalfSpace:
      x << "type=\"plane\" size=\"0 0 1\"/>";
      break;
  }
  return x.str();
}

struct Loaded {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  ~Loaded() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
};

// Loads `xml` through a temporary file; on failure sets `error`.
void load(const std::string& xml, Loaded& out, std::string& error) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("tribo_peer_" + std::to_string(::getpid()) + ".xml");
  {
    std::ofstream f(path);
    f << xml;
  }
  char message[1000] = "";
  out.m = mj_loadXML(path.c_str(), nullptr, message, sizeof message);
  std::filesystem::remove(path);
  if (!out.m) {
    error = std::string("MuJoCo: ") + message;
    return;
  }
  out.d = mj_makeData(out.m);
  if (!out.d) error = "MuJoCo: mj_makeData failed";
}

void contacts(const Loaded& l, PeerRun& run) {
  run.points = l.d->ncon;
  run.penetration = 0;
  for (int i = 0; i < l.d->ncon; ++i)
    run.penetration = std::max(run.penetration, -static_cast<double>(l.d->contact[i].dist));
  if (l.d->warning[mjWARN_CONTACTFULL].number > 0 || l.d->warning[mjWARN_CNSTRFULL].number > 0)
    run.error = "MuJoCo: contact or constraint buffer full";
  if (l.d->warning[mjWARN_BADQACC].number > 0) run.error = "MuJoCo: diverged (bad qacc)";
}

}  // namespace

std::string mujocoVersion() { return std::to_string(mj_version()); }

PeerRun runMujoco(const PeerScene& scene, double max_bytes, const std::string& solver) {
  PeerRun run;
  run.steps = scene.steps;
  // Room for 5 contacts per body (a resting box has 4; the pile 2.6 per sphere); a full
  // buffer is reported as an error.
  long ncon = 0, nv = 0;
  for (const PeerBody& p : scene.bodies)
    if (p.dynamic) {
      ncon += 5;
      nv += 6;
    }
  const double njmax = 4.0 * static_cast<double>(ncon);
  const double bytes = 12.0 * njmax * (njmax + 2.0 * static_cast<double>(nv));
  if (bytes > max_bytes) {
    char s[200];
    std::snprintf(s, sizeof s,
                  "not run: MuJoCo 2.2 would allocate about %.1f GB of constraint arrays "
                  "(njmax %.0f x (njmax + 2 nv), nv %ld)",
                  bytes / 1e9, njmax, nv);
    run.error = s;
    return run;
  }
  std::ostringstream x;
  x << header(scene.dt, scene.gravity, scene.mu, ncon, solver);
  for (const PeerBody& p : scene.bodies) {
    Eigen::Isometry3d body_pose = Eigen::Isometry3d::Identity();
    body_pose.linear() = p.orientation.toRotationMatrix();
    body_pose.translation() = p.position;
    if (!p.dynamic) {
      for (const PeerShape& s : p.shapes) x << "    " << geom(s, body_pose * s.pose) << "\n";
      continue;
    }
    x << "    <body pos=\"" << vec(p.position) << "\" quat=\"" << quat(p.orientation)
      << "\"><freejoint/><inertial pos=\"0 0 0\" mass=\"" << p.mass << "\" diaginertia=\""
      << vec(p.inertia) << "\"/>" << geom(p.shapes[0], Eigen::Isometry3d::Identity())
      << "</body>\n";
  }
  x << "  </worldbody>\n</mujoco>\n";
  Loaded l;
  load(x.str(), l, run.error);
  if (!run.error.empty()) return run;
  const StepTimer timer;
  for (long i = 0; i < scene.steps; ++i) mj_step(l.m, l.d);
  timer.stop(run);
  contacts(l, run);
  std::vector<Eigen::Vector3d> positions(scene.bodies.size());
  int body = 1;  // MuJoCo's body 0 is the world; dynamic bodies follow in order
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    positions[b] = scene.bodies[b].position;
    if (!scene.bodies[b].dynamic) continue;
    const mjtNum* p = l.d->xpos + 3 * body;
    positions[b] = {p[0], p[1], p[2]};
    const mjtNum* v = l.d->qvel + l.m->jnt_dofadr[l.m->body_jntadr[body]];  // free joint: v, w
    run.max_speed = std::max(run.max_speed, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    ++body;
  }
  run.drift = horizontalDrift(scene, positions);
  return run;
}

// The belt: a long box on a slide joint along x with a mass of 1e6 kg started at v_b (MuJoCo
// has no surface velocity, and a mocap body's motion does not enter contact velocities); the
// friction of the block (29 N) slows it by 6e-5 m/s in 2 s. The block slides along x and z
// (two slide joints, no rotation); the spring is the x joint's stiffness. Measured: MuJoCo's
// block hops while it slides (up to about 1 mm above the belt, often with no contact at the
// last step, so its penetration and points read 0), with pyramidal or elliptic cones alike.
PeerRun runMujocoBelt(const BeltSpec& belt) {
  PeerRun run;
  run.steps = belt.steps;
  const Eigen::Vector3d h = belt.half_extents;
  const double inertia = belt.mass * (h.x() * h.x() + h.z() * h.z()) / 3.0;  // unused (no rotation)
  std::ostringstream x;
  x << header(belt.dt, Eigen::Vector3d(0, 0, -belt.g), belt.mu, 16, "Newton")
    << "    <body name=\"belt\" pos=\"0 0 -0.05\"><joint name=\"belt\" type=\"slide\" "
       "axis=\"1 0 0\"/><inertial pos=\"0 0 0\" mass=\"1e6\" diaginertia=\"1e6 1e6 1e6\"/>"
       "<geom type=\"box\" size=\"50 1 0.05\"/></body>\n"
    << "    <body name=\"block\" pos=\"0 0 " << h.z() << "\"><joint name=\"x\" type=\"slide\" "
    << "axis=\"1 0 0\" stiffness=\"" << belt.spring << "\"/><joint name=\"z\" type=\"slide\" "
    << "axis=\"0 0 1\"/><inertial pos=\"0 0 0\" mass=\"" << belt.mass << "\" diaginertia=\""
    << inertia << " " << inertia << " " << inertia << "\"/><geom type=\"box\" size=\"" << vec(h)
    << "\"/></body>\n"
    << "  </worldbody>\n</mujoco>\n";
  Loaded l;
  load(x.str(), l, run.error);
  if (!run.error.empty()) return run;
  l.d->qvel[0] = belt.belt_speed;
  const StepTimer timer;
  for (long i = 0; i < belt.steps; ++i) mj_step(l.m, l.d);
  timer.stop(run);
  contacts(l, run);
  const double xb = l.d->qpos[1];
  run.belt_error = std::abs(xb - belt.exactX(belt.dt * static_cast<double>(belt.steps)));
  if (!std::isfinite(xb)) run.error = "diverged";
  return run;
}

}  // namespace tribo::peers
