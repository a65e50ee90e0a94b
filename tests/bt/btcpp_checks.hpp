// Checks of exported files against BehaviorTree.CPP's own rules, without
// BehaviorTree.CPP: xmllint with the schema its writeTreeXSD() writes
// (bt::btcpp_xsd_for), and the node paths its TreeObserver keys on (the rule of
// XMLParser::createNodeFromXML: path = the name attribute, or the ID when there is
// none; "::<uid>" is appended when the name equals the ID; a repeated path makes
// the TreeObserver constructor throw).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "rtamp/bt/xml_dom.hpp"
#include "rtamp/bt/xml_schema.hpp"

namespace rtamp::bt::testing {

inline bool have_xmllint() { return std::system("xmllint --version > /dev/null 2>&1") == 0; }

// xmllint's complaints about `xml` against the schema for its own <TreeNodesModel>;
// empty when it validates.
inline std::string xmllint_errors(const std::string& xml, const std::string& xsd) {
  static int serial = 0;
  char dir_template[] = "/tmp/rtamp_btxml_XXXXXX";
  const char* dir = mkdtemp(dir_template);
  if (dir == nullptr) return "cannot make a temporary directory";
  const std::string base = std::string(dir) + "/t" + std::to_string(serial++);
  std::ofstream(base + ".xml") << xml;
  std::ofstream(base + ".xsd") << xsd;
  const std::string cmd = "xmllint --noout --schema " + base + ".xsd " + base + ".xml 2>&1";
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
    const int status = pclose(p);
    std::remove((base + ".xml").c_str());
    std::remove((base + ".xsd").c_str());
    std::remove(dir);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
    return out.empty() ? "xmllint failed" : out;
  }
  return "cannot run xmllint";
}

inline std::string schema_errors(const std::string& xml) { return xmllint_errors(xml, btcpp_xsd_for(xml)); }

// TreeObserver paths that occur more than once in the main tree of `xml`.
inline std::vector<std::string> repeated_paths(const std::string& xml) {
  const XmlDocument doc = parse_xml(xml);
  std::map<std::string, int> count;
  int uid = 0;
  std::function<void(const XmlElement&)> walk = [&](const XmlElement& e) {
    ++uid;
    const std::string* name = e.attribute("name");
    std::string path = name != nullptr ? *name : e.tag;
    if (path == e.tag) path += "::" + std::to_string(uid);
    ++count[path];
    for (const XmlElement& c : e.children) walk(c);
  };
  for (const XmlElement& t : doc.root.children) {
    if (t.tag == "BehaviorTree") {
      for (const XmlElement& c : t.children) walk(c);
    }
  }
  std::vector<std::string> out;
  for (const auto& [path, n] : count) {
    if (n > 1) out.push_back(path);
  }
  return out;
}

}  // namespace rtamp::bt::testing
