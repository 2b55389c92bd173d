// The friction laws at the parameters of the seed paper's Table 1 (Roh & Yoo 2007: mu_s 0.35,
// mu_k 0.3, v_s 0.01 m/s, a 1.5, beta 1/3; v_d 0.15 m/s for the two-step laws), and stribeck
// with v_st = 0.1 m/s and viscous 0.01 s/m, for the friction tests and benches.
#pragma once

#include <string>

#include "friction/friction_law.hpp"

namespace tribo::test {

inline friction::LawSpec table1(const std::string& name) {
  if (name == "coulomb") return {"coulomb", {{"mu", 0.3}}, {}};
  if (name == "roh_yoo")
    return {
        name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}}, {}};
  if (name == "stribeck")
    return {name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_st", 0.1}, {"viscous", 0.01}}, {}};
  return {name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"v_d", 0.15}}, {}};
}

}  // namespace tribo::test
