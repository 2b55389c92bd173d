// Checks of a URDF's XML that run before urdfdom sees the text, each refusing with a
// UrdfError "FILE:LINE: what, expected what, found what":
//   - urdfXmlNesting: elements nested deeper than kMaxUrdfNesting (TinyXML and urdfdom walk
//     the element tree by recursion; a URDF nests 5 levels);
//   - indexUrdfXml: links and joints by name, with their lines; every joint's type, parent and
//     child; at most kMaxUrdfLinks links; the links form one tree (each link the child of at
//     most one joint, no loop, one root). Linear in the number of links, without recursion.
//   - checkUrdfValues: every number Tribo reads (masses, inertias, origins, axes, limits,
//     dynamics, collision geometry sizes, mesh scales, mimic factors, <gazebo> mu1 mu2 kp kd)
//     is finite, and those that cannot be negative are not. Visual elements are not checked
//     (Tribo does not use them).
// Not here: the model checks that give findings rather than errors (io/urdf_checks.hpp).
#pragma once

#include <cstddef>
#include <map>
#include <string>

class TiXmlElement;

namespace tribo::io {

// Most links a URDF may have: loading is linear in the links (about 0.1 ms each, most of it
// urdfdom's parse), so this bounds a load to about 10 s.
inline constexpr std::size_t kMaxUrdfLinks = 100000;
// Deepest element nesting a URDF may have (its own elements nest at most 5 deep).
inline constexpr int kMaxUrdfNesting = 200;

struct UrdfXmlIndex {
  std::map<std::string, const TiXmlElement*> links, joints;
  std::string root;  // the one link that is no joint's child
};

// Throws UrdfError naming `path` when the text's elements nest deeper than kMaxUrdfNesting.
// A scan of the text (comments, CDATA, declarations and quoted attribute values skipped).
void checkUrdfNesting(const std::string& text, const std::string& path);

UrdfXmlIndex indexUrdfXml(const TiXmlElement* robot, const std::string& path);

void checkUrdfValues(const TiXmlElement* robot, const std::string& path);

}  // namespace tribo::io
