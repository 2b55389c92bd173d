// What a scene's contact materials are, for a reader: the normal law and its constants, the
// friction law's name, the limit surface of an anisotropic material (contact/anisotropy.hpp:
// per sense, the coefficient's ratios along the grain and across it, so that the limit
// surface is the half-ellipse with semi-axes r1 mu F_n and r2 mu F_n), and the rolling and
// spinning resistance's thresholds (moment per newton of load) and angular springs
// (contact/rolling_resistance.hpp). One source for summary.json's settings.materials and for
// `tribo info` on a scene.
// Not here: the friction laws' own parameters (each law keeps its own; the scene file states
// them), contact pairs (the caller says which pairs use a material).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "contact/contact_force.hpp"

namespace tribo::study {

// summary.json's entry for one material (keys: normal_law, stiffness, damping, friction_law,
// and when they apply exponent, max_depth, anisotropy, rolling, spinning).
nlohmann::json materialJson(const contact::Material& material);

// The same as lines of text, the first naming the normal and friction laws, one more for each
// of anisotropy, rolling and spinning that the material has.
std::vector<std::string> describeMaterial(const contact::Material& material);

}  // namespace tribo::study
