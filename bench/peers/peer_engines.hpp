// The peers' runs of a PeerScene or the belt, each defined only when its engine was found
// (TRIBO_PEER_BULLET, TRIBO_PEER_MUJOCO; bench/peers/CMakeLists.txt). Written against each
// engine's public API; every engine keeps its own contact model, solver and friction (Coulomb
// with the scene's mu), at the scene's step, in double precision.
#pragma once

#include <string>

#include "peer_scene.hpp"

namespace tribo::peers {

// Bullet: btDiscreteDynamicsWorld (dynamic AABB tree broadphase, sequential-impulse solver,
// its defaults: 10 iterations, split impulse), one stepSimulation per step with no substeps;
// sleeping switched off so that resting bodies are stepped as moving ones are.
PeerRun runBullet(const PeerScene& scene);
PeerRun runBulletBelt(const BeltSpec& belt);
std::string bulletVersion();

// MuJoCo: the scene as MJCF (free joints, its default soft contacts, pyramidal cones),
// semi-implicit Euler (its "Euler"), `solver` "Newton" (its default), "CG" or "PGS".
// `max_bytes`: a run whose constraint arrays (sized by njmax x nv and njmax x njmax in MuJoCo
// 2.2) would take more is not made.
PeerRun runMujoco(const PeerScene& scene, double max_bytes, const std::string& solver);
PeerRun runMujocoBelt(const BeltSpec& belt);
std::string mujocoVersion();

}  // namespace tribo::peers
