// Checks shared by the friction laws' constructors, so every law words its parameter
// errors the same way: "LAW: RULE (got VALUE)", thrown as FrictionParameterError.
// Not a parser: the factory (friction_law.cpp) maps scene keys to parameter structs.
#pragma once

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "friction/friction_law.hpp"

namespace tribo::friction {

class ParameterCheck {
 public:
  explicit ParameterCheck(std::string_view law) : law_(law) {}

  // Every value finite: "KEY must be a finite number (got nan)".
  void finite(std::initializer_list<std::pair<const char*, double>> values) const {
    for (const auto& [key, value] : values)
      require(std::isfinite(value), std::string(key) + " must be a finite number", value);
  }
  // Throws "LAW: RULE (got VALUE)" unless ok.
  void require(bool ok, const std::string& rule, double got) const {
    if (!ok) fail(rule + " (got " + number(got) + ")");
  }
  // Throws "LAW: RULE (got A_NAME = A, B_NAME = B)" unless ok.
  void require(bool ok, const std::string& rule, const char* a_name, double a, const char* b_name,
               double b) const {
    if (!ok)
      fail(rule + " (got " + a_name + " = " + number(a) + ", " + b_name + " = " + number(b) + ")");
  }
  // The usual pair: mu_k >= 0 and mu_s >= mu_k.
  void staticAtLeastKinetic(double mu_s, double mu_k) const {
    require(mu_k >= 0.0, "mu_k must be >= 0", mu_k);
    require(mu_s >= mu_k, "mu_s must be >= mu_k", "mu_s", mu_s, "mu_k", mu_k);
  }
  // The bristle laws' shared set (lugre, elasto_plastic): finite, sigma0 > 0 [1/m],
  // sigma1, sigma2 >= 0 [s/m], mu_s >= mu_c > 0, v_s > 0 [m/s].
  void bristle(double sigma0, double sigma1, double sigma2, double mu_c, double mu_s,
               double v_s) const {
    finite({{"sigma0", sigma0},
            {"sigma1", sigma1},
            {"sigma2", sigma2},
            {"mu_c", mu_c},
            {"mu_s", mu_s},
            {"v_s", v_s}});
    require(sigma0 > 0.0, "sigma0 must be > 0 [1/m]", sigma0);
    require(sigma1 >= 0.0, "sigma1 must be >= 0 [s/m]", sigma1);
    require(sigma2 >= 0.0, "sigma2 must be >= 0 [s/m]", sigma2);
    require(mu_c > 0.0, "mu_c must be > 0", mu_c);
    require(mu_s >= mu_c, "mu_s must be >= mu_c", "mu_s", mu_s, "mu_c", mu_c);
    require(v_s > 0.0, "v_s must be > 0 [m/s]", v_s);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw FrictionParameterError(law_ + ": " + what);
  }

  static std::string number(double value) {
    std::ostringstream os;
    os.precision(15);
    os << value;
    return os.str();
  }

 private:
  std::string law_;
};

}  // namespace tribo::friction
