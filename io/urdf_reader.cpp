#include "io/urdf_reader.hpp"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "io/file_read.hpp"
#include "io/urdf_checks.hpp"
#include "io/urdf_xml_checks.hpp"
#include "io/utf8_check.hpp"

namespace tribo::io {

namespace {

// Collects urdfdom's console messages while it parses, instead of printing them.
// console_bridge has one process-wide handler: this one is installed once and files each
// message with the thread that is parsing, so files parsed at once on several threads (a
// sweep's points) keep their messages apart without a lock of ours.
class MessageCollector : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN && sink) sink->push_back(text);
  }
  static thread_local std::vector<std::string>* sink;
};
thread_local std::vector<std::string>* MessageCollector::sink = nullptr;

// urdfdom's parse with its messages gathered into `messages`.
urdf::ModelInterfaceSharedPtr parseCollecting(const std::string& xml,
                                              std::vector<std::string>& messages) {
  static MessageCollector collector;
  static const bool installed = (console_bridge::useOutputHandler(&collector), true);
  (void)installed;
  MessageCollector::sink = &messages;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  MessageCollector::sink = nullptr;
  return model;
}

// urdfdom's links own their children (Link::child_links), so letting go of the root of a
// long chain destroyed it link within link, in a recursion as deep as the chain (a 100 000-link
// chain overflowed a 512 kB stack). Each link lets go of its children first, while the model
// still holds every link; then the model frees them one by one.
struct ModelTeardown {
  const urdf::ModelInterfaceSharedPtr& model;
  ~ModelTeardown() {
    if (!model) return;
    for (auto& [name, link] : model->links_) {
      if (!link) continue;
      link->child_links.clear();
      link->child_joints.clear();
    }
  }
};

Eigen::Isometry3d toIsometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  double x, y, z, w;
  p.rotation.getQuaternion(x, y, z, w);
  t.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  return t;
}

std::optional<double> number(const char* text) {
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text) return std::nullopt;
  while (*end == ' ' || *end == '\n' || *end == '\t') ++end;
  if (*end != '\0') return std::nullopt;
  return v;
}

std::vector<double> numbers(const char* text) {
  std::vector<double> out;
  if (!text) return out;
  std::istringstream s(text);
  double v;
  while (s >> v) out.push_back(v);
  return out;
}

// <origin xyz rpy> of an element, URDF convention R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Isometry3d originOf(const TiXmlElement* parent) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const TiXmlElement* o = parent->FirstChildElement("origin");
  if (!o) return t;
  const auto xyz = numbers(o->Attribute("xyz"));
  const auto rpy = numbers(o->Attribute("rpy"));
  if (xyz.size() == 3) t.translation() = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
  if (rpy.size() == 3)
    t.linear() = (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
  return t;
}

class Reader {
 public:
  Reader(const std::string& path, const PackagePaths& packages, const UrdfReadOptions& options)
      : path_(path), packages_(packages), options_(options) {}

  UrdfRobot read() {
    std::string text;
    try {
      text = readFileBounded(path_, "URDF file", kMaxUrdfBytes);
    } catch (const FileReadError& e) {
      throw UrdfError(e.what());
    }
    return parse(text);
  }

  UrdfRobot parse(const std::string& text) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
      throw UrdfError(at(0) + "the file is empty (expected a <robot> XML document)");
    // TinyXML 2.6 steps over a multi-byte character by its lead byte alone, so a lead byte
    // at the end of the text made it read past the buffer (found by fuzz/urdf_fuzzer).
    if (const std::size_t bad = firstBadUtf8(text); bad != std::string::npos)
      throw UrdfError(at(positionOf(text, bad).line) + "expected UTF-8 text, found " +
                      badUtf8Reason(text, bad));
    checkUrdfNesting(text, path_);
    TiXmlDocument doc;
    doc.Parse(text.c_str());
    if (doc.Error() && doc.ErrorId() == TiXmlBase::TIXML_ERROR_DOCUMENT_EMPTY)
      // TinyXML's words for "no element found": the text does not start with '<'.
      throw UrdfError(at(1) + "not an XML document: it starts with '" + opening(text) +
                      "' (expected a <robot> XML document)");
    if (doc.Error())
      throw UrdfError(at(doc.ErrorRow()) + "malformed XML: " + doc.ErrorDesc() + " (column " +
                      std::to_string(doc.ErrorCol()) + ")");
    TiXmlElement* robot = doc.RootElement();
    if (!robot || std::string(robot->Value()) != "robot")
      throw UrdfError(at(robot ? robot->Row() : 0) + "expected a <robot> root element, found <" +
                      (robot ? robot->Value() : "") + ">");
    std::vector<UrdfIssue> repairs;
    std::set<std::string> unlimited;
    if (!options_.strict) repair(robot, repairs, unlimited);
    const UrdfXmlIndex index = indexUrdfXml(robot, path_);
    checkUrdfValues(robot, path_);
    std::string xml = text;
    if (!repairs.empty()) {
      TiXmlPrinter printer;
      doc.Accept(&printer);
      xml = printer.CStr();
    }

    std::vector<std::string> messages;
    const urdf::ModelInterfaceSharedPtr model = parseCollecting(xml, messages);
    const ModelTeardown teardown{model};
    if (!model) {
      std::string why;
      for (const auto& m : messages) why += (why.empty() ? "" : "; ") + m;
      throw UrdfError(at(0) +
                      "urdfdom rejected the file: " + (why.empty() ? "no reason given" : why));
    }
    UrdfRobot r;
    r.name = model->getName();
    r.path = path_;
    const urdf::LinkConstSharedPtr root = model->getRoot();
    if (!root) throw UrdfError(at(0) + "no root link");
    r.root = root->name;
    addTree(r, root, index);
    for (auto& j : r.joints)
      if (unlimited.count(j.name)) j.has_limits = false;
    readGazebo(r, robot);
    r.issues.insert(r.issues.begin(), repairs.begin(), repairs.end());
    checkUrdfRobot(r);
    return r;
  }

 private:
  std::string at(int line) const {
    std::ostringstream s;
    s << path_;
    if (line > 0) s << ':' << line;
    s << ": ";
    return s.str();
  }

  // The first characters of a file, printable, for a message.
  static std::string opening(const std::string& text) {
    std::string out;
    for (char c : text.substr(text.find_first_not_of(" \t\r\n"), 24)) {
      if (c == '\n' || c == '\r') break;
      out += (c >= 32 && c < 127) ? c : '?';
    }
    return out;
  }

  // What other tools accept and urdfdom refuses, repaired in the document before urdfdom
  // parses it: a revolute or prismatic joint without <limit> gets a placeholder (the joint is
  // then read as unlimited), and an undeclared parent link named `world` is declared (a
  // massless root: the world frame).
  void repair(TiXmlElement* robot, std::vector<UrdfIssue>& repairs,
              std::set<std::string>& unlimited) const {
    std::set<std::string> links;
    for (const TiXmlElement* e = robot->FirstChildElement("link"); e;
         e = e->NextSiblingElement("link"))
      if (e->Attribute("name")) links.insert(e->Attribute("name"));
    bool world_used = false;
    for (TiXmlElement* e = robot->FirstChildElement("joint"); e;
         e = e->NextSiblingElement("joint")) {
      const char* name = e->Attribute("name");
      const char* type = e->Attribute("type");
      if (!name || !type) continue;
      const std::string t = type;
      if ((t == "revolute" || t == "prismatic") && !e->FirstChildElement("limit")) {
        TiXmlElement limit("limit");
        for (const char* key : {"lower", "upper", "effort", "velocity"})
          limit.SetAttribute(key, "0");
        e->InsertEndChild(limit);
        unlimited.insert(name);
        repairs.push_back({UrdfIssue::Severity::kNote, "joint '" + std::string(name) + "'",
                           "line " + std::to_string(e->Row()) + ": " + t +
                               " joint without <limit>: loaded as unlimited (--strict refuses "
                               "it, as urdfdom does)"});
      }
      const TiXmlElement* parent = e->FirstChildElement("parent");
      const char* link = parent ? parent->Attribute("link") : nullptr;
      if (link && std::string(link) == "world" && !links.count("world") && !world_used) {
        world_used = true;
        repairs.push_back({UrdfIssue::Severity::kNote, "link 'world'",
                           "line " + std::to_string(parent->Row()) +
                               ": parent 'world' is not declared: taken as the world frame "
                               "(--strict refuses it, as urdfdom does)"});
      }
    }
    if (world_used) {
      TiXmlElement world("link");
      world.SetAttribute("name", "world");
      robot->InsertEndChild(world);
    }
  }

  // Links parents first, depth first in urdfdom's order of children, each after the joint
  // above it; with a stack of its own, as a chain of links is as deep as it is long.
  void addTree(UrdfRobot& r, const urdf::LinkConstSharedPtr& root, const UrdfXmlIndex& index) {
    std::vector<urdf::LinkConstSharedPtr> stack{root};
    while (!stack.empty()) {
      const urdf::LinkConstSharedPtr link = stack.back();
      stack.pop_back();
      if (link != root && link->parent_joint) addJoint(r, *link->parent_joint, index);
      addLink(r, link, index);
      for (auto c = link->child_links.rbegin(); c != link->child_links.rend(); ++c)
        stack.push_back(*c);
    }
  }

  void addLink(UrdfRobot& r, const urdf::LinkConstSharedPtr& link, const UrdfXmlIndex& index) {
    UrdfLink l;
    l.name = link->name;
    const auto it = index.links.find(l.name);
    const TiXmlElement* xml = it != index.links.end() ? it->second : nullptr;
    l.line = xml ? xml->Row() : 0;
    if (link->inertial) {
      const urdf::Inertial& in = *link->inertial;
      l.has_inertial = true;
      l.mass = in.mass;
      l.inertial_origin = toIsometry(in.origin);
      l.inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    }
    int xml_collisions = 0;
    if (xml)
      for (const TiXmlElement* c = xml->FirstChildElement("collision"); c;
           c = c->NextSiblingElement("collision"))
        ++xml_collisions;
    if (xml && xml_collisions > static_cast<int>(link->collision_array.size())) {
      readCollisionsFromXml(r, l, xml);
    } else {
      for (const auto& c : link->collision_array) addCollision(r, l, *c);
    }
    r.links.push_back(l);
  }

  void addJoint(UrdfRobot& r, const urdf::Joint& j, const UrdfXmlIndex& index) {
    UrdfJoint u;
    u.name = j.name;
    const auto it = index.joints.find(j.name);
    u.line = it != index.joints.end() ? it->second->Row() : 0;
    static const std::map<int, std::string> kNames{
        {urdf::Joint::FIXED, "fixed"},           {urdf::Joint::REVOLUTE, "revolute"},
        {urdf::Joint::CONTINUOUS, "continuous"}, {urdf::Joint::PRISMATIC, "prismatic"},
        {urdf::Joint::FLOATING, "floating"},     {urdf::Joint::PLANAR, "planar"}};
    u.type = kNames.count(j.type) ? kNames.at(j.type) : "unknown";
    u.parent = j.parent_link_name;
    u.child = j.child_link_name;
    u.origin = toIsometry(j.parent_to_joint_origin_transform);
    const Eigen::Vector3d axis(j.axis.x, j.axis.y, j.axis.z);
    if (axis.norm() > 0.0) {
      u.axis = axis.normalized();
    } else if (u.type != "fixed" && u.type != "floating") {
      r.issues.push_back(
          {UrdfIssue::Severity::kError, "joint '" + u.name + "'", "axis has zero length"});
    }
    if (j.limits) {
      u.has_limits = true;
      u.lower = j.limits->lower;
      u.upper = j.limits->upper;
      u.effort = j.limits->effort;
      u.velocity = j.limits->velocity;
    }
    if (j.dynamics) {
      u.damping = j.dynamics->damping;
      u.friction = j.dynamics->friction;
    }
    if (j.mimic) {
      u.mimic_joint = j.mimic->joint_name;
      u.mimic_multiplier = j.mimic->multiplier;
      u.mimic_offset = j.mimic->offset;
    }
    r.joints.push_back(u);
  }

  void resolveMesh(UrdfRobot& r, const UrdfLink& l, UrdfCollision& c) {
    const auto folder = std::filesystem::path(path_).parent_path().string();
    const auto res = packages_.resolve(c.mesh_uri, folder.empty() ? "." : folder);
    if (res.path) {
      c.mesh_path = *res.path;
      return;
    }
    std::string tried;
    for (const auto& t : res.tried) tried += (tried.empty() ? "" : ", ") + t;
    r.issues.push_back({UrdfIssue::Severity::kError, "link '" + l.name + "'",
                        "collision mesh '" + c.mesh_uri + "': " + res.problem +
                            (tried.empty() ? "" : " (tried: " + tried + ")")});
  }

  void addCollision(UrdfRobot& r, UrdfLink& l, const urdf::Collision& c) {
    if (!c.geometry) return;
    UrdfCollision u;
    u.origin = toIsometry(c.origin);
    switch (c.geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& b = static_cast<const urdf::Box&>(*c.geometry);
        u.kind = UrdfCollision::Kind::kBox;
        u.size = Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z);
        break;
      }
      case urdf::Geometry::SPHERE:
        u.kind = UrdfCollision::Kind::kSphere;
        u.radius = static_cast<const urdf::Sphere&>(*c.geometry).radius;
        break;
      case urdf::Geometry::CYLINDER: {
        const auto& cy = static_cast<const urdf::Cylinder&>(*c.geometry);
        u.kind = UrdfCollision::Kind::kCylinder;
        u.radius = cy.radius;
        u.length = cy.length;
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& m = static_cast<const urdf::Mesh&>(*c.geometry);
        u.kind = UrdfCollision::Kind::kMesh;
        u.mesh_uri = m.filename;
        u.scale = Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z);
        resolveMesh(r, l, u);
        break;
      }
    }
    l.collisions.push_back(u);
  }

  // urdfdom stops at the first collision geometry it does not know (capsule) and keeps
  // none of that link's collisions; read them here instead.
  void readCollisionsFromXml(UrdfRobot& r, UrdfLink& l, const TiXmlElement* link) {
    for (const TiXmlElement* c = link->FirstChildElement("collision"); c;
         c = c->NextSiblingElement("collision")) {
      const TiXmlElement* g = c->FirstChildElement("geometry");
      const TiXmlElement* shape = g ? g->FirstChildElement() : nullptr;
      if (!shape) continue;
      const std::string kind = shape->Value();
      UrdfCollision u;
      u.origin = originOf(c);
      if (kind == "box") {
        const auto size = numbers(shape->Attribute("size"));
        if (size.size() != 3) continue;
        u.kind = UrdfCollision::Kind::kBox;
        u.size = Eigen::Vector3d(size[0], size[1], size[2]);
      } else if (kind == "sphere" || kind == "cylinder" || kind == "capsule") {
        u.kind = kind == "sphere"     ? UrdfCollision::Kind::kSphere
                 : kind == "cylinder" ? UrdfCollision::Kind::kCylinder
                                      : UrdfCollision::Kind::kCapsule;
        u.radius = number(shape->Attribute("radius")).value_or(0.0);
        u.length = number(shape->Attribute("length")).value_or(0.0);
      } else if (kind == "mesh") {
        u.kind = UrdfCollision::Kind::kMesh;
        u.mesh_uri = shape->Attribute("filename") ? shape->Attribute("filename") : "";
        const auto scale = numbers(shape->Attribute("scale"));
        if (scale.size() == 3) u.scale = Eigen::Vector3d(scale[0], scale[1], scale[2]);
        resolveMesh(r, l, u);
      } else {
        r.issues.push_back({UrdfIssue::Severity::kWarning, "link '" + l.name + "'",
                            "line " + std::to_string(shape->Row()) +
                                ": unknown collision geometry <" + kind + ">, ignored"});
        continue;
      }
      l.collisions.push_back(u);
    }
    r.issues.push_back({UrdfIssue::Severity::kWarning, "link '" + l.name + "'",
                        "collision elements read by Tribo: urdfdom dropped some (a geometry it "
                        "does not know, such as <capsule>, or a sphere of radius 0)"});
  }

  void readGazebo(UrdfRobot& r, const TiXmlElement* robot) {
    std::map<std::string, std::size_t> link_index;
    for (std::size_t i = 0; i < r.links.size(); ++i) link_index.emplace(r.links[i].name, i);
    for (const TiXmlElement* g = robot->FirstChildElement("gazebo"); g;
         g = g->NextSiblingElement("gazebo")) {
      const char* ref = g->Attribute("reference");
      if (!ref) continue;
      const auto found = link_index.find(ref);
      if (found == link_index.end()) continue;
      UrdfLink* link = &r.links[found->second];
      auto read = [&](const char* tag, std::optional<double>& into) {
        if (const TiXmlElement* e = g->FirstChildElement(tag)) {
          const auto v = number(e->GetText());
          if (v)
            into = v;
          else
            r.issues.push_back({UrdfIssue::Severity::kWarning, "link '" + link->name + "'",
                                "line " + std::to_string(e->Row()) + ": <gazebo><" + tag +
                                    "> is not a number, ignored"});
        }
      };
      read("mu1", link->contact.mu1);
      read("mu2", link->contact.mu2);
      read("kp", link->contact.kp);
      read("kd", link->contact.kd);
    }
  }

  std::string path_;
  const PackagePaths& packages_;
  UrdfReadOptions options_;
};

}  // namespace

double UrdfRobot::totalMass() const {
  double m = 0.0;
  for (const auto& l : links) m += l.has_inertial ? l.mass : 0.0;
  return m;
}

const UrdfLink* UrdfRobot::findLink(const std::string& n) const {
  for (const auto& l : links)
    if (l.name == n) return &l;
  return nullptr;
}

const UrdfJoint* UrdfRobot::parentJoint(const std::string& link) const {
  for (const auto& j : joints)
    if (j.child == link) return &j;
  return nullptr;
}

bool UrdfRobot::hasErrors() const {
  for (const auto& i : issues)
    if (i.severity == UrdfIssue::Severity::kError) return true;
  return false;
}

UrdfRobot readUrdf(const std::string& path, const PackagePaths& packages,
                   const UrdfReadOptions& options) {
  return Reader(path, packages, options).read();
}

bool looksLikeUrdf(const std::string& path) {
  std::error_code ec;  // only a regular file is opened: a FIFO would block, a device not end
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::size_t i = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // UTF-8 byte-order mark
  while (i < head.size()) {
    i = head.find_first_not_of(" \t\r\n", i);
    if (i == std::string::npos || head[i] != '<') return false;
    if (head.compare(i, 4, "<!--") == 0) {
      i = head.find("-->", i);
      if (i == std::string::npos) return false;
      i += 3;
    } else if (head.compare(i, 2, "<?") == 0 || head.compare(i, 2, "<!") == 0) {
      i = head.find('>', i);
      if (i == std::string::npos) return false;
      ++i;
    } else {
      const std::size_t end = head.find_first_of(" \t\r\n/>", i + 1);
      return head.substr(i + 1, end == std::string::npos ? end : end - i - 1) == "robot";
    }
  }
  return false;
}

UrdfRobot readUrdfFromString(const std::string& xml, const std::string& name_for_errors,
                             const PackagePaths& packages, const UrdfReadOptions& options) {
  return Reader(name_for_errors, packages, options).parse(xml);
}

}  // namespace tribo::io
