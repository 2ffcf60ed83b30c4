#include "ek/rod/material.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "ek/core/errors.hpp"

namespace ek {

namespace {
std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}
}  // namespace

double RodMaterial::shear_modulus() const { return young / (2.0 * (1.0 + poisson)); }

double RodMaterial::bending_stiffness() const { return young * M_PI * std::pow(radius, 4) / 4.0; }

double RodMaterial::twisting_stiffness() const { return shear_modulus() * M_PI * std::pow(radius, 4) / 2.0; }

double RodMaterial::stretching_stiffness() const { return young * M_PI * radius * radius; }

void RodMaterial::validate() const {
  require_input(std::isfinite(young) && young > 0.0,
                "Young's modulus must be a positive finite number, got " + str(young));
  require_input(std::isfinite(radius) && radius > 0.0,
                "wire radius must be a positive finite number, got " + str(radius));
  require_input(std::isfinite(poisson) && poisson > -1.0 && poisson <= 0.5,
                "Poisson ratio must be in (-1, 0.5], got " + str(poisson));
}

}  // namespace ek
