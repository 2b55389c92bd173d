// A contact pair: two geometries (by index in Model::geometries) and their contact material
// (by index in Model::materials). Listed in Model::contact_pairs, or derived on demand from
// a pair id for automatic contacts (core/automatic_contacts.hpp).
#pragma once

namespace tribo {

struct ContactPair {
  int geometry_a = -1;  // normal and friction forces are reported on B
  int geometry_b = -1;
  int material = -1;
};

}  // namespace tribo
