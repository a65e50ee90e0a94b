#include "rtamp/bt/xml_schema.hpp"

#include <map>
#include <sstream>

#include "rtamp/bt/xml_export.hpp"

namespace rtamp::bt {

namespace {

constexpr const char* kInt = "integerOrBlackboardType";
constexpr const char* kBool = "booleanOrBlackboardType";
constexpr const char* kString = "stringOrBlackboardType";
constexpr const char* kBlackboard = "blackboardType";

ModelPort req(std::string name, std::string type = {}) { return ModelPort{std::move(name), std::move(type), {}, {}}; }
ModelPort opt(std::string name, std::string type, std::string def) {
  return ModelPort{std::move(name), std::move(type), std::move(def), {}};
}

std::vector<NodeModel> make_builtins() {
  std::vector<NodeModel> m;
  for (const char* id : {"Fallback", "AsyncFallback", "Sequence", "AsyncSequence", "SequenceWithMemory",
                         "ReactiveSequence", "ReactiveFallback", "IfThenElse", "WhileDoElse"})
    m.push_back({id, "Control", {}});
  m.push_back({"Parallel", "Control", {opt("success_count", kInt, "-1"), opt("failure_count", kInt, "1")}});
  m.push_back({"ParallelAll", "Control", {opt("max_failures", kInt, "1")}});
  m.push_back({"TryCatch", "Control", {opt("catch_on_halt", kBool, "false")}});
  for (int n = 2; n <= 6; ++n) {
    NodeModel sw{"Switch" + std::to_string(n), "Control", {req("variable", kString)}};
    for (int i = 1; i <= n; ++i) sw.ports.push_back(req("case_" + std::to_string(i), kString));
    m.push_back(std::move(sw));
  }
  for (const char* id : {"Inverter", "KeepRunningUntilFailure", "ForceSuccess", "ForceFailure"})
    m.push_back({id, "Decorator", {}});
  m.push_back({"RetryUntilSuccessful", "Decorator", {req("num_attempts", kInt)}});
  m.push_back({"Repeat", "Decorator", {req("num_cycles", kInt)}});
  m.push_back({"Timeout", "Decorator", {req("msec", kInt)}});
  m.push_back({"Delay", "Decorator", {req("delay_msec", kInt)}});
  m.push_back({"RunOnce", "Decorator", {opt("then_skip", kBool, "true")}});
  m.push_back({"Precondition", "Decorator", {req("if", kString), opt("else", "", "FAILURE")}});
  for (const char* id : {"LoopInt", "LoopBool", "LoopDouble", "LoopString"})
    m.push_back({id, "Decorator", {req("queue"), opt("if_empty", "", "SUCCESS"), req("value", kBlackboard)}});
  for (const char* id : {"SkipUnlessUpdated", "WaitValueUpdate"}) m.push_back({id, "Decorator", {req("entry")}});
  for (const char* id : {"AlwaysSuccess", "AlwaysFailure"}) m.push_back({id, "Action", {}});
  m.push_back({"Script", "Action", {req("code", kString)}});
  m.push_back({"ScriptCondition", "Condition", {req("code")}});
  m.push_back({"SetBlackboard", "Action", {req("value"), req("output_key")}});
  m.push_back({"Sleep", "Action", {req("msec", kInt)}});
  m.push_back({"UnsetBlackboard", "Action", {req("key", kString)}});
  m.push_back({"WasEntryUpdated", "Action", {req("entry")}});
  m.push_back({"SubTree", "SubTree", {opt("_autoremap", kBool, "false")}});
  return m;
}

// writeTreeXSD's attribute type for a <TreeNodesModel> port.
std::string xsd_type(std::string_view element, const std::string* type) {
  if (element == "output_port") return kBlackboard;
  if (type == nullptr) return {};
  if (*type == "int" || *type == "unsigned int" || *type == "unsigned") return kInt;
  if (*type == "double") return "decimalOrBlackboardType";
  if (*type == "bool") return kBool;
  if (*type == "std::string" || *type == "std::__cxx11::basic_string<char, std::char_traits<char>, "
                                         "std::allocator<char> >")
    return kString;
  return {};
}

constexpr const char* kCommon = R"(  <!-- Define the common elements -->
  <xs:simpleType name="blackboardType">
    <xs:restriction base="xs:string">
      <xs:pattern value="\{.*\}"/>
    </xs:restriction>
  </xs:simpleType>
  <xs:simpleType name="booleanOrBlackboardType">
    <xs:union memberTypes="xs:boolean blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="integerOrBlackboardType">
    <xs:union memberTypes="xs:integer blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="decimalOrBlackboardType">
    <xs:union memberTypes="xs:decimal blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="stringOrBlackboardType">
    <xs:union memberTypes="xs:string blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="descriptionType">
    <xs:restriction base="xs:string">
      <xs:whiteSpace value="preserve"/>
    </xs:restriction>
  </xs:simpleType>
  <xs:complexType name="inputPortType">
    <xs:simpleContent>
      <xs:extension base="xs:string">
        <xs:attribute name="name" type="xs:string" use="required"/>
        <xs:attribute name="type" type="xs:string" use="optional"/>
        <xs:attribute name="default" type="xs:string" use="optional"/>
      </xs:extension>
    </xs:simpleContent>
  </xs:complexType>
  <xs:complexType name="outputPortType">
    <xs:simpleContent>
      <xs:extension base="xs:string">
        <xs:attribute name="name" type="xs:string" use="required"/>
        <xs:attribute name="type" type="xs:string" use="optional"/>
      </xs:extension>
    </xs:simpleContent>
  </xs:complexType>
  <xs:attributeGroup name="preconditionAttributeGroup">
    <xs:attribute name="_failureIf" type="xs:string" use="optional"/>
    <xs:attribute name="_skipIf" type="xs:string" use="optional"/>
    <xs:attribute name="_successIf" type="xs:string" use="optional"/>
    <xs:attribute name="_while" type="xs:string" use="optional"/>
  </xs:attributeGroup>
  <xs:attributeGroup name="postconditionAttributeGroup">
    <xs:attribute name="_onSuccess" type="xs:string" use="optional"/>
    <xs:attribute name="_onFailure" type="xs:string" use="optional"/>
    <xs:attribute name="_post" type="xs:string" use="optional"/>
    <xs:attribute name="_onHalted" type="xs:string" use="optional"/>
  </xs:attributeGroup>
  <xs:attributeGroup name="commonAttributeGroup">
    <xs:attribute name="name" type="xs:string" use="optional"/>
    <xs:attributeGroup ref="preconditionAttributeGroup"/>
    <xs:attributeGroup ref="postconditionAttributeGroup"/>
  </xs:attributeGroup>
  <xs:complexType name="treeNodesModelNodeType">
    <xs:sequence>
      <xs:choice minOccurs="0" maxOccurs="unbounded">
        <xs:element name="input_port" type="inputPortType"/>
        <xs:element name="output_port" type="outputPortType"/>
      </xs:choice>
      <xs:element name="description" type="descriptionType" minOccurs="0" maxOccurs="1"/>
    </xs:sequence>
    <xs:attribute name="ID" type="xs:string" use="required"/>
  </xs:complexType>
  <xs:group name="treeNodesModelNodeGroup">
    <xs:choice>
      <xs:element name="Action" type="treeNodesModelNodeType"/>
      <xs:element name="Condition" type="treeNodesModelNodeType"/>
      <xs:element name="Control" type="treeNodesModelNodeType"/>
      <xs:element name="Decorator" type="treeNodesModelNodeType"/>
    </xs:choice>
  </xs:group>
  <xs:element name="root">
    <xs:complexType>
      <xs:sequence>
        <xs:choice minOccurs="0" maxOccurs="unbounded">
          <xs:element ref="include"/>
          <xs:element ref="BehaviorTree"/>
        </xs:choice>
        <xs:element ref="TreeNodesModel" minOccurs="0" maxOccurs="1"/>
      </xs:sequence>
      <xs:attribute name="BTCPP_format" type="xs:string" use="required"/>
      <xs:attribute name="main_tree_to_execute" type="xs:string" use="optional"/>
    </xs:complexType>
  </xs:element>
)";

constexpr const char* kElements = R"(  <xs:element name="include">
    <xs:complexType>
      <xs:attribute name="path" type="xs:string" use="required"/>
      <xs:attribute name="ros_pkg" type="xs:string" use="optional"/>
    </xs:complexType>
  </xs:element>
  <xs:element name="BehaviorTree">
    <xs:complexType>
      <xs:group ref="oneNodeGroup"/>
      <xs:attribute name="ID" type="xs:string" use="required"/>
    </xs:complexType>
  </xs:element>
  <xs:element name="TreeNodesModel">
    <xs:complexType>
      <xs:group ref="treeNodesModelNodeGroup" minOccurs="0" maxOccurs="unbounded"/>
    </xs:complexType>
  </xs:element>
)";

}  // namespace

const std::vector<NodeModel>& btcpp_builtin_models() {
  static const std::vector<NodeModel> models = make_builtins();
  return models;
}

std::string port_name_problem(std::string_view name) {
  if (name.empty()) return "it is empty";
  if (name.front() >= '0' && name.front() <= '9') return "it starts with a digit";
  if (name == "ID" || name == "name" || name.front() == '_') return "it is a reserved attribute";
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80) continue;  // UTF-8 multibyte sequences are allowed
    if (c < 32 || c == 127) return "it holds a control character";
    if (std::string_view(" <>&\"'/\\:*?|.").find(ch) != std::string_view::npos)
      return std::string("it holds the character '") + ch + "'";
  }
  return {};
}

std::vector<NodeModel> read_tree_nodes_model(const XmlDocument& doc, const std::string& file) {
  std::vector<NodeModel> out;
  std::map<std::string, const XmlElement*, std::less<>> declared;
  for (const XmlElement& section : doc.root.children) {
    if (section.tag != "TreeNodesModel") continue;
    for (const XmlElement& e : section.children) {
      const std::string* id = e.attribute("ID");
      if (id == nullptr || id->empty()) {
        throw rtamp::Error("<" + e.tag + "> in <TreeNodesModel> has no ID", location_of(e, file));
      }
      if (e.tag != "Action" && e.tag != "Condition" && e.tag != "Control" && e.tag != "Decorator" &&
          e.tag != "SubTree") {
        throw rtamp::Error("<" + e.tag + " ID=\"" + *id +
                               "\"> in <TreeNodesModel>: expected Action, Condition, Control, Decorator or SubTree",
                           location_of(e, file));
      }
      if (auto [it, fresh] = declared.emplace(*id, &e); !fresh) {
        throw rtamp::Error("'" + *id + "' is declared twice in <TreeNodesModel> (as <" + it->second->tag + "> on line " +
                               std::to_string(it->second->line) + " and as <" + e.tag + "> here)",
                           location_of(e, file));
      }
      NodeModel m{*id, e.tag, {}};
      for (const XmlElement& p : e.children) {
        if (p.tag == "description" || p.tag == "metadata") continue;
        if (p.tag != "input_port" && p.tag != "output_port" && p.tag != "inout_port") {
          throw rtamp::Error("<" + p.tag + "> in the model of '" + *id + "': expected input_port, output_port or inout_port",
                             location_of(p, file));
        }
        const std::string* name = p.attribute("name");
        if (name == nullptr || name->empty()) {
          throw rtamp::Error("<" + p.tag + "> in the model of '" + *id + "' has no name", location_of(p, file));
        }
        if (const std::string why = port_name_problem(*name); !why.empty()) {
          throw rtamp::Error("port name '" + *name + "' in the model of '" + *id + "' is not allowed: " + why,
                             location_of(p, file));
        }
        for (const ModelPort& q : m.ports) {
          if (q.name == *name) {
            throw rtamp::Error("port '" + *name + "' is declared twice in the model of '" + *id + "'", location_of(p, file));
          }
        }
        ModelPort port{*name, xsd_type(p.tag, p.attribute("type")), {}, p.text};
        if (const std::string* d = p.attribute("default"); d != nullptr && p.tag != "output_port") port.default_value = *d;
        m.ports.push_back(std::move(port));
      }
      out.push_back(std::move(m));
    }
  }
  return out;
}

std::string btcpp_xsd(const std::vector<NodeModel>& custom) {
  std::map<std::string, const NodeModel*> models;  // ordered by ID, as writeTreeXSD
  for (const NodeModel& m : btcpp_builtin_models()) models[m.id] = &m;
  for (const NodeModel& m : custom) models[m.id] = &m;
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!-- The schema BehaviorTree.CPP 4's writeTreeXSD() writes for these nodes (written by rtamp) -->\n"
      << "<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\" elementFormDefault=\"qualified\">\n"
      << kCommon << "  <xs:group name=\"oneNodeGroup\">\n    <xs:choice>\n";
  for (const auto& [id, m] : models)
    out << "      <xs:element name=\"" << xml_escape(id) << "\" type=\"" << xml_escape(id) << "Type\"/>\n";
  out << "    </xs:choice>\n  </xs:group>\n" << kElements;
  for (const auto& [id, m] : models) {
    out << "  <xs:complexType name=\"" << xml_escape(id) << "Type\">\n";
    if (m->kind == "Decorator") {
      out << "    <xs:group ref=\"oneNodeGroup\" minOccurs=\"1\" maxOccurs=\"1\"/>\n";
    } else if (m->kind == "Control") {
      out << "    <xs:group ref=\"oneNodeGroup\" minOccurs=\"0\" maxOccurs=\"unbounded\"/>\n";
    }
    out << "    <xs:attributeGroup ref=\"commonAttributeGroup\"/>\n";
    for (const ModelPort& p : m->ports) {
      out << "    <xs:attribute name=\"" << xml_escape(p.name) << '"';
      if (!p.xsd_type.empty()) out << " type=\"" << p.xsd_type << '"';
      if (p.default_value) {
        out << " default=\"" << xml_escape(*p.default_value) << "\"/>\n";
      } else {
        out << " use=\"required\"/>\n";
      }
    }
    if (m->kind == "SubTree") {
      out << "    <xs:attribute name=\"ID\" type=\"xs:string\" use=\"required\"/>\n"
          << "    <xs:anyAttribute processContents=\"skip\"/>\n";
    }
    out << "  </xs:complexType>\n";
  }
  out << "</xs:schema>\n";
  return out.str();
}

std::string btcpp_xsd_for(std::string_view xml, const std::string& file) {
  return btcpp_xsd(read_tree_nodes_model(parse_xml(xml, file), file));
}

}  // namespace rtamp::bt
