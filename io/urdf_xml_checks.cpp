#include "io/urdf_xml_checks.hpp"

#include <tinyxml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

#include "io/urdf_reader.hpp"

namespace tribo::io {

namespace {

const std::set<std::string> kJointTypes{"fixed",     "revolute", "continuous",
                                        "prismatic", "floating", "planar"};

std::string at(const std::string& path, int line) {
  return path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": ";
}

int lineAt(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
}

// The offset just past `close` from `from`, or the end of the text.
std::size_t skipPast(const std::string& text, std::size_t from, const char* close) {
  const std::size_t end = text.find(close, from);
  return end == std::string::npos ? text.size() : end + std::char_traits<char>::length(close);
}

const char* parentLink(const TiXmlElement* joint) {
  return joint->FirstChildElement("parent")->Attribute("link");
}

// A URDF is a tree: every link is the child of at most one joint, following parents from
// any link ends at a root, and there is one root. Each link is visited once: a walk up from a
// link stops at a link an earlier walk finished.
std::string checkTree(const UrdfXmlIndex& index, const std::string& path) {
  std::map<std::string, const TiXmlElement*> parent_joint;  // child link -> its joint
  for (const auto& [name, e] : index.joints) {
    const std::string child = e->FirstChildElement("child")->Attribute("link");
    const auto [it, fresh] = parent_joint.emplace(child, e);
    if (!fresh)
      throw UrdfError(at(path, e->Row()) + "joint '" + name + "': link '" + child +
                      "' is already the child of joint '" + it->second->Attribute("name") +
                      "' (line " + std::to_string(it->second->Row()) +
                      "); a URDF is a tree, each link has one parent");
  }
  enum State { kNew, kOnWalk, kDone };
  std::map<std::string, State> state;
  std::vector<std::string> walk;
  for (const auto& [start, link_element] : index.links) {
    if (state[start] == kDone) continue;
    walk.assign(1, start);
    state[start] = kOnWalk;
    for (auto it = parent_joint.find(start); it != parent_joint.end();
         it = parent_joint.find(walk.back())) {
      const std::string parent = parentLink(it->second);
      State& s = state[parent];
      if (s == kDone) break;
      if (s == kOnWalk) {
        // From `parent` down the walk and back to it; a long loop by its ends and length.
        const std::size_t m =
            static_cast<std::size_t>(std::find(walk.begin(), walk.end(), parent) - walk.begin());
        const std::size_t n = walk.size() - m;  // links in the loop
        std::string loop = parent;
        for (std::size_t k = 0; k < n; ++k) {
          if (n > 12 && k == 5) {
            loop += " -> ... (" + std::to_string(n) + " links in all)";
            k = n - 6;
            continue;
          }
          loop += " -> " + walk[walk.size() - 1 - k];
        }
        throw UrdfError(at(path, it->second->Row()) + "no root link: joint '" +
                        it->second->Attribute("name") + "' closes the kinematic loop " + loop +
                        " (a URDF is a tree; close loops in a scene file instead)");
      }
      s = kOnWalk;
      walk.push_back(parent);
    }
    for (const std::string& l : walk) state[l] = kDone;
  }
  std::vector<std::string> roots;
  for (const auto& [name, e] : index.links)
    if (!parent_joint.count(name)) roots.push_back(name);
  if (roots.size() != 1) {  // none only without links: a loop is found above
    std::string names;
    for (std::size_t i = 0; i < roots.size() && i < 5; ++i)
      names += (i ? ", '" : "'") + roots[i] + "' (line " +
               std::to_string(index.links.at(roots[i])->Row()) + ")";
    if (roots.size() > 5) names += " and " + std::to_string(roots.size() - 5) + " more";
    throw UrdfError(at(path, 0) + "expected one root link (a link that is no joint's child), " +
                    "found " + std::to_string(roots.size()) + (roots.empty() ? "" : ": " + names) +
                    "; a URDF is one tree");
  }
  return roots.front();
}

// A number attribute: its name, and whether it may be negative.
struct Rule {
  const char* attribute;
  bool non_negative;
};

class ValueChecker {
 public:
  explicit ValueChecker(const std::string& path) : path_(path) {}

  // Every number of `element`'s attributes in `rules`, when present.
  void check(const TiXmlElement* element, const std::string& where,
             std::initializer_list<Rule> rules) const {
    if (!element) return;
    for (const Rule& r : rules) {
      const char* text = element->Attribute(r.attribute);
      if (text)
        checkText(text, element->Row(), where, "attribute '" + std::string(r.attribute) + "'",
                  r.non_negative);
    }
  }

  // An element's text (the <gazebo> tags).
  void checkElementText(const TiXmlElement* element, const std::string& where) const {
    if (element && element->GetText())
      checkText(element->GetText(), element->Row(), where, "its text", true);
  }

 private:
  // Each whitespace-separated word that is a number must be finite (and >= 0 when
  // `non_negative`); words that are not numbers are left to urdfdom, which refuses them.
  void checkText(const std::string& text, int line, const std::string& where,
                 const std::string& what, bool non_negative) const {
    std::size_t i = 0;
    while ((i = text.find_first_not_of(" \t\r\n", i)) != std::string::npos) {
      const std::size_t end = std::min(text.find_first_of(" \t\r\n", i), text.size());
      const std::string word = text.substr(i, end - i);
      i = end;
      char* stop = nullptr;
      const double v = std::strtod(word.c_str(), &stop);
      if (stop != word.c_str() + word.size()) continue;
      if (std::isfinite(v) && (!non_negative || !(v < 0.0))) continue;
      throw UrdfError(at(path_, line) + where + ": " + what + ": expected " +
                      (non_negative ? "finite numbers >= 0" : "finite numbers") + ", found '" +
                      text + "'");
    }
  }

  const std::string& path_;
};

void checkOrigin(const ValueChecker& c, const TiXmlElement* parent, const std::string& where) {
  c.check(parent->FirstChildElement("origin"), where + "/origin", {{"xyz", false}, {"rpy", false}});
}

void checkLink(const ValueChecker& c, const TiXmlElement* link, const std::string& who) {
  if (const TiXmlElement* in = link->FirstChildElement("inertial")) {
    const std::string where = who + "/inertial";
    checkOrigin(c, in, where);
    c.check(in->FirstChildElement("mass"), where + "/mass", {{"value", true}});
    c.check(in->FirstChildElement("inertia"), where + "/inertia",
            {{"ixx", false},
             {"ixy", false},
             {"ixz", false},
             {"iyy", false},
             {"iyz", false},
             {"izz", false}});
  }
  for (const TiXmlElement* col = link->FirstChildElement("collision"); col;
       col = col->NextSiblingElement("collision")) {
    const std::string where = who + "/collision";
    checkOrigin(c, col, where);
    const TiXmlElement* g = col->FirstChildElement("geometry");
    for (const TiXmlElement* s = g ? g->FirstChildElement() : nullptr; s;
         s = s->NextSiblingElement()) {
      const std::string shape = where + "/geometry/" + s->Value();
      c.check(s, shape, {{"size", true}, {"radius", true}, {"length", true}});
      c.check(s, shape, {{"scale", false}});  // a negative scale mirrors a mesh
    }
  }
}

void checkJoint(const ValueChecker& c, const TiXmlElement* joint, const std::string& who) {
  checkOrigin(c, joint, who);
  c.check(joint->FirstChildElement("axis"), who + "/axis", {{"xyz", false}});
  c.check(joint->FirstChildElement("limit"), who + "/limit",
          {{"lower", false}, {"upper", false}, {"effort", true}, {"velocity", true}});
  c.check(joint->FirstChildElement("dynamics"), who + "/dynamics",
          {{"damping", true}, {"friction", true}});
  c.check(joint->FirstChildElement("mimic"), who + "/mimic",
          {{"multiplier", false}, {"offset", false}});
}

}  // namespace

void checkUrdfNesting(const std::string& text, const std::string& path) {
  int depth = 0;
  for (std::size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i)) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = skipPast(text, i, "-->");
    } else if (text.compare(i, 9, "<![CDATA[") == 0) {
      i = skipPast(text, i, "]]>");
    } else if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
      i = skipPast(text, i, ">");
    } else if (text.compare(i, 2, "</") == 0) {
      --depth;
      i = skipPast(text, i, ">");
    } else {
      // A start tag: to its '>' outside quoted values; "/>" closes it at once.
      std::size_t k = i + 1;
      char quote = 0;
      for (; k < text.size(); ++k) {
        if (quote) {
          if (text[k] == quote) quote = 0;
        } else if (text[k] == '"' || text[k] == '\'') {
          quote = text[k];
        } else if (text[k] == '>') {
          break;
        }
      }
      if (k >= text.size() || text[k - 1] != '/') ++depth;
      if (depth > kMaxUrdfNesting)
        throw UrdfError(at(path, lineAt(text, i)) + "elements nested more than " +
                        std::to_string(kMaxUrdfNesting) +
                        " deep (the most a URDF may nest, docs/urdf.md)");
      i = k;
    }
  }
}

UrdfXmlIndex indexUrdfXml(const TiXmlElement* robot, const std::string& path) {
  std::size_t count = 0;
  for (const TiXmlElement* e = robot->FirstChildElement("link"); e;
       e = e->NextSiblingElement("link"))
    ++count;
  if (count > kMaxUrdfLinks)
    throw UrdfError(at(path, 0) + std::to_string(count) + " links: expected at most " +
                    std::to_string(kMaxUrdfLinks) + " (the most a URDF may have, docs/urdf.md)");
  UrdfXmlIndex index;
  for (const TiXmlElement* e = robot->FirstChildElement("link"); e;
       e = e->NextSiblingElement("link")) {
    const char* name = e->Attribute("name");
    if (!name) throw UrdfError(at(path, e->Row()) + "<link> without a name");
    if (!index.links.emplace(name, e).second)
      throw UrdfError(at(path, e->Row()) + "link '" + name + "' is defined twice");
  }
  for (const TiXmlElement* e = robot->FirstChildElement("joint"); e;
       e = e->NextSiblingElement("joint")) {
    const char* name = e->Attribute("name");
    if (!name) throw UrdfError(at(path, e->Row()) + "<joint> without a name");
    const std::string who = "joint '" + std::string(name) + "'";
    index.joints.emplace(name, e);
    const char* type = e->Attribute("type");
    if (!type || !kJointTypes.count(type))
      throw UrdfError(at(path, e->Row()) + who + ": unknown type '" + (type ? type : "") +
                      "' (expected one of: fixed, revolute, continuous, prismatic, floating, "
                      "planar)");
    for (const char* role : {"parent", "child"}) {
      const TiXmlElement* p = e->FirstChildElement(role);
      const char* link = p ? p->Attribute("link") : nullptr;
      if (!link) throw UrdfError(at(path, e->Row()) + who + ": no <" + role + " link=...>");
      if (!index.links.count(link))
        throw UrdfError(at(path, p->Row()) + who + ": " + role + " link '" + link +
                        "' is not defined");
    }
  }
  if (!index.links.empty()) index.root = checkTree(index, path);
  return index;
}

void checkUrdfValues(const TiXmlElement* robot, const std::string& path) {
  const ValueChecker c(path);
  for (const TiXmlElement* e = robot->FirstChildElement("link"); e;
       e = e->NextSiblingElement("link"))
    checkLink(c, e, "link '" + std::string(e->Attribute("name") ? e->Attribute("name") : "") + "'");
  for (const TiXmlElement* e = robot->FirstChildElement("joint"); e;
       e = e->NextSiblingElement("joint"))
    checkJoint(c, e,
               "joint '" + std::string(e->Attribute("name") ? e->Attribute("name") : "") + "'");
  for (const TiXmlElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    const char* ref = g->Attribute("reference");
    const std::string who = "gazebo reference '" + std::string(ref ? ref : "") + "'";
    for (const char* tag : {"mu1", "mu2", "kp", "kd"})
      c.checkElementText(g->FirstChildElement(tag), who + "/" + tag);
  }
}

}  // namespace tribo::io
