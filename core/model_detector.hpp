// The collision detector of a model: its geometries' shapes, its listed contact pairs or its
// rule of automatic ones (core/automatic_contacts.hpp, asked on demand), its collision
// options, and the watchdog on each FCL query (contact/query_watchdog.hpp): a query that runs
// past CollisionOptions::query_time_limit ends the process with kQueryOverrunStatus, naming
// the two geometries and their bodies (FCL/libccd cannot be interrupted). Not here: what is
// done with the contact points (core/dynamics.hpp).
#pragma once

#include <memory>

#include "contact/collision_detector.hpp"
#include "core/model.hpp"

namespace tribo {

// Exit status of a process ended by the collision-query watchdog (README, "Exit status").
inline constexpr int kQueryOverrunStatus = 7;

contact::CollisionDetector makeModelDetector(const std::shared_ptr<const Model>& model);

}  // namespace tribo
