// LAMMPS's runs of the granular cases of bench/peers (lammps_peer.hpp): the PeerScene's spheres
// created as atoms at the scene's positions (lammps_create_atoms), its kinematic half-spaces
// and axis-aligned boxes turned into fix wall/gran planes (a box gives the face towards the
// spheres along its thinnest axis, as an unbounded plane: right while the spheres stay within
// the box's span), stepped by `run`. The contacts are counted here from the atoms' positions
// after each chunk of steps, outside the clock: a sphere pair closer than two radii, or a
// sphere closer than its radius to a wall, is one contact, as LAMMPS applies a force exactly
// then. Not a general LAMMPS front end: one atom type, equal spheres, planes only; and Debian's
// build has no C++ exceptions, so an input LAMMPS refuses ends the process (its message goes
// nowhere: -screen none).
#include "lammps_peer.hpp"

#include <lammps/library.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace tribo::peers {

namespace {

std::string num(double v) {
  char s[64];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

// A wall plane x[axis] = at; `lower`: the solid is below (the spheres on the + side).
struct Wall {
  int axis = 2;
  bool lower = true;
  double at = 0.0;
};

// The axis a unit vector lies along (its sign in `sign`), or -1 when it is tilted.
int axisOf(const Eigen::Vector3d& n, double& sign) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(std::abs(n[a]) - 1.0) < 1e-12) {
      sign = n[a] > 0 ? 1.0 : -1.0;
      return a;
    }
  return -1;
}

std::vector<Wall> wallsOf(const PeerScene& scene, const Eigen::Vector3d& centre) {
  std::vector<Wall> walls;
  for (const PeerBody& b : scene.bodies) {
    if (b.dynamic) continue;
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translate(b.position);
    body.rotate(b.orientation);
    for (const PeerShape& s : b.shapes) {
      const Eigen::Isometry3d pose = body * s.pose;
      const Eigen::Matrix3d r = pose.linear();
      const Eigen::Vector3d p = pose.translation();
      Wall w;
      if (s.kind == PeerShape::Kind::kHalfSpace) {
        double sign = 1.0;
        w.axis = axisOf(r.col(2), sign);
        if (w.axis < 0) throw std::invalid_argument("lammps peer: a tilted half-space");
        w.lower = sign > 0;
        w.at = p[w.axis];
      } else if (s.kind == PeerShape::Kind::kBox) {
        Eigen::Vector3d half = Eigen::Vector3d::Zero();
        for (int c = 0; c < 3; ++c) {
          double sign = 1.0;
          const int a = axisOf(r.col(c), sign);
          if (a < 0) throw std::invalid_argument("lammps peer: a box wall not along the axes");
          half[a] = s.half_extents[c];
        }
        half.minCoeff(&w.axis);
        w.lower = centre[w.axis] > p[w.axis];
        w.at = p[w.axis] + (w.lower ? half[w.axis] : -half[w.axis]);
      } else {
        throw std::invalid_argument("lammps peer: a sphere on a fixed body");
      }
      walls.push_back(w);
    }
  }
  return walls;
}

// Contact points and the deepest one among n spheres of radius r (positions x[i][0..2]).
struct Count {
  long points = 0;
  double deepest = 0.0;
};

Count countContacts(double** x, int n, double r, const std::vector<Wall>& walls) {
  Count count;
  const double cell = 2.0 * r;
  auto key = [](long ix, long iy, long iz) {
    return ((ix + (1L << 20)) << 42) | ((iy + (1L << 20)) << 21) | (iz + (1L << 20));
  };
  std::unordered_map<long, std::vector<int>> cells;
  std::vector<std::array<long, 3>> at(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    auto& c = at[static_cast<std::size_t>(i)];
    for (int a = 0; a < 3; ++a) c[a] = std::lround(std::floor(x[i][a] / cell));
    cells[key(c[0], c[1], c[2])].push_back(i);
  }
  for (int i = 0; i < n; ++i) {
    const auto& c = at[static_cast<std::size_t>(i)];
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells.end()) continue;
          for (int j : it->second) {
            if (j <= i) continue;
            const double d = std::hypot(x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]);
            if (d < 2.0 * r) {
              ++count.points;
              count.deepest = std::max(count.deepest, 2.0 * r - d);
            }
          }
        }
    for (const Wall& w : walls) {
      const double gap = w.lower ? x[i][w.axis] - w.at : w.at - x[i][w.axis];
      if (gap < r) {
        ++count.points;
        count.deepest = std::max(count.deepest, r - gap);
      }
    }
  }
  return count;
}

using Handle = std::unique_ptr<void, void (*)(void*)>;

Handle open() {
  const char* args[] = {"tribo_peer", "-log", "none", "-screen", "none", "-nocite"};
  void* h = lammps_open_no_mpi(6, const_cast<char**>(args), nullptr);
  if (h == nullptr) throw std::runtime_error("lammps peer: lammps_open_no_mpi failed");
  return Handle(h, lammps_close);
}

void command(void* h, const std::string& c) { lammps_command(h, c.c_str()); }

}  // namespace

GranularRun runLammps(const PeerScene& scene, const GranularLaw& law, double skin, int samples) {
  if (!lammps_config_has_package("GRANULAR"))
    throw std::runtime_error("lammps peer: this LAMMPS has no GRANULAR package");
  GranularRun out;
  std::vector<double> x;
  double radius = 0.0, mass = 0.0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo, centre = Eigen::Vector3d::Zero();
  for (const PeerBody& b : scene.bodies) {
    if (!b.dynamic) continue;
    if (b.shapes.size() != 1 || b.shapes[0].kind != PeerShape::Kind::kSphere)
      throw std::invalid_argument("lammps peer: body '" + b.name + "' is not one sphere");
    if (out.spheres == 0) radius = b.shapes[0].radius, mass = b.mass;
    if (b.shapes[0].radius != radius || b.mass != mass)
      throw std::invalid_argument("lammps peer: spheres of different radii or masses");
    for (int a = 0; a < 3; ++a) x.push_back(b.position[a]);
    lo = lo.cwiseMin(b.position);
    hi = hi.cwiseMax(b.position);
    centre += b.position;
    ++out.spheres;
  }
  if (out.spheres == 0) throw std::invalid_argument("lammps peer: no spheres");
  centre /= static_cast<double>(out.spheres);
  const std::vector<Wall> walls = wallsOf(scene, centre);

  const double kn = law.stiffness, kt = 2.0 / 7.0 * kn;
  const double gn_pair = law.damping / (mass / 2.0), gn_wall = law.damping / mass;
  const std::string mu = num(scene.mu);

  Handle lmp = open();
  void* h = lmp.get();
  for (const char* c : {"units si", "atom_style sphere", "atom_modify map array", "boundary s s s",
                        "comm_modify vel yes"})
    command(h, c);
  command(h, "region domain block " + num(lo.x() - radius) + " " + num(hi.x() + radius) + " " +
                 num(lo.y() - radius) + " " + num(hi.y() + radius) + " " + num(lo.z() - radius) +
                 " " + num(hi.z() + radius));
  command(h, "create_box 1 domain");
  const int n = static_cast<int>(out.spheres);
  std::vector<int> ids(static_cast<std::size_t>(n)), types(static_cast<std::size_t>(n), 1);
  for (int i = 0; i < n; ++i) ids[static_cast<std::size_t>(i)] = i + 1;
  if (lammps_create_atoms(h, n, ids.data(), types.data(), x.data(), nullptr, nullptr, 0) != n)
    throw std::runtime_error("lammps peer: lammps_create_atoms did not create every sphere");
  command(h, "set type 1 diameter " + num(2.0 * radius));
  command(h, "set type 1 mass " + num(mass));
  const std::string pair_law =
      num(kn) + " " + num(kt) + " " + num(gn_pair) + " " + num(gn_pair / 2.0) + " " + mu + " 1";
  const std::string wall_law =
      num(kn) + " " + num(kt) + " " + num(gn_wall) + " " + num(gn_wall / 2.0) + " " + mu + " 1";
  command(h, "pair_style gran/hooke/history " + pair_law);
  command(h, "pair_coeff * *");
  command(h, "neighbor " + num(skin) + " bin");
  command(h, "neigh_modify every 1 delay 0 check yes");
  command(h, "timestep " + num(scene.dt));
  command(h, "fix integrate all nve/sphere");
  const double g = scene.gravity.norm();
  command(h, "fix gravity all gravity " + num(g) + " vector " + num(scene.gravity.x() / g) + " " +
                 num(scene.gravity.y() / g) + " " + num(scene.gravity.z() / g));
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const Wall& w = walls[i];
    const std::string lohi = w.lower ? num(w.at) + " NULL" : "NULL " + num(w.at);
    command(h, "fix wall" + std::to_string(i) + " all wall/gran hooke/history " + wall_law + " " +
                   "xyz"[w.axis] + "plane " + lohi);
  }
  command(h, "thermo 0");
  command(h, "run 0 post no");  // set-up (neighbour lists, forces at the start): not timed

  const auto* rmass = static_cast<const double*>(lammps_extract_atom(h, "rmass"));
  const auto* rad = static_cast<const double*>(lammps_extract_atom(h, "radius"));
  if (rmass == nullptr || rad == nullptr || std::abs(rmass[0] - mass) > 1e-12 * mass ||
      std::abs(rad[0] - radius) > 1e-12 * radius)
    throw std::runtime_error("lammps peer: the atoms' mass or radius is not the scene's");

  out.run.steps = scene.steps;
  double points = 0.0;
  long done = 0;
  for (int k = 0; k < samples; ++k) {
    const long chunk = (scene.steps * (k + 1)) / samples - done;
    PeerRun part;
    const StepTimer timer;
    command(h, "run " + std::to_string(chunk) + " pre no post no");
    timer.stop(part);
    out.run.seconds += part.seconds;
    out.run.cpu_seconds += part.cpu_seconds;
    done += chunk;
    const int nlocal = lammps_extract_setting(h, "nlocal");
    const Count c =
        countContacts(static_cast<double**>(lammps_extract_atom(h, "x")), nlocal, radius, walls);
    points += static_cast<double>(c.points);
    out.run.points = static_cast<double>(c.points);
    out.run.penetration = c.deepest;
  }
  out.mean_points = points / samples;
  const int nlocal = lammps_extract_setting(h, "nlocal");
  if (nlocal != n) out.run.error = "lammps peer: spheres were lost";
  auto** v = static_cast<double**>(lammps_extract_atom(h, "v"));
  for (int i = 0; i < nlocal; ++i)
    out.run.max_speed = std::max(out.run.max_speed, std::hypot(v[i][0], v[i][1], v[i][2]));

  char s[512];
  std::snprintf(s, sizeof s,
                "LAMMPS %d, 1 thread; pair gran/hooke/history kn %g kt %g gamman %g/s gammat "
                "%g/s xmu %g dampflag 1; %zu wall/gran planes gamman %g/s; nve/sphere (velocity "
                "Verlet) dt %g s; neighbor %g m bin, every 1 delay 0 check yes; newton on; "
                "boundary s s s",
                lammps_version(h), kn, kt, gn_pair, gn_pair / 2.0, scene.mu, walls.size(), gn_wall,
                scene.dt, skin);
  out.settings = s;
  return out;
}

std::string lammpsVersion() {
  Handle lmp = open();
  return std::to_string(lammps_version(lmp.get())) +
         (lammps_config_has_package("GRANULAR") ? " (GRANULAR)" : " (no GRANULAR package)");
}

void lammpsFinish() { lammps_mpi_finalize(); }

}  // namespace tribo::peers
