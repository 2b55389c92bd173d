#include "contact/shape.hpp"

#include <limits>

namespace tribo::contact {

double Shape::size() const {
  if (type == ShapeType::kHalfSpace) return std::numeric_limits<double>::infinity();
  return half_extents.minCoeff();
}

std::string shapeName(ShapeType type) {
  switch (type) {
    case ShapeType::kBox:
      return "box";
    case ShapeType::kHalfSpace:
      return "halfspace";
  }
  return "unknown";
}

}  // namespace tribo::contact
