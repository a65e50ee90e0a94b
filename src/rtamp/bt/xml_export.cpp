#include "rtamp/bt/xml_export.hpp"

#include <cstdio>
#include <map>
#include <sstream>

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (c == '\t' || c == '\n' || c == '\r') {
          char buf[8];
          std::snprintf(buf, sizeof buf, "&#%d;", static_cast<int>(c));
          out += buf;  // kept through attribute-value normalisation
        } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          out += "\xEF\xBF\xBD";  // U+FFFD: XML 1.0 has no other control characters
        } else {
          out += c;
        }
    }
  }
  return out;
}

namespace {

struct ModelEntry {
  NodeKind kind;
  std::vector<Port> ports;        // union over instances, first-seen order
  std::vector<int> port_uses;     // instances that carry ports[i]
  int instances = 0;
};

std::string_view placeholder_for(const Node& node) {
  const std::string_view t = node.type_id();
  if (t == "Sequence" || t == "ReactiveSequence" || t == "Parallel") return "AlwaysSuccess";
  return "AlwaysFailure";
}

class XmlWriter : public Visitor {
 public:
  XmlWriter(std::ostringstream& out, const XmlOptions& opt,
            std::map<std::string, ModelEntry, std::less<>>& model, std::vector<std::string>& model_order)
      : out_(out), opt_(opt), model_(model), model_order_(model_order) {}

  bool enter(const Node& node, int depth) override {
    if (node.kind() == NodeKind::Decorator && node.child_count() != 1) {
      throw rtamp::Error("cannot export behavior tree: decorator '" + node.name() + "' has no child");
    }
    if (!node.btcpp_builtin()) record_model(node);
    ++preorder_;
    indent(depth);
    out_ << '<' << node.type_id() << " name=\"" << xml_escape(node.name());
    if (opt_.unique_names) out_ << " #" << (node.id() != kNoId ? node.id() : preorder_);
    out_ << '"';
    ports_.clear();
    node.collect_ports(ports_);
    for (const Port& p : ports_) out_ << ' ' << p.name << "=\"" << xml_escape(p.value) << '"';
    const bool leaf = node.kind() == NodeKind::Action || node.kind() == NodeKind::Condition;
    if (leaf) {
      out_ << "/>\n";
      return false;
    }
    out_ << ">\n";
    if (node.child_count() == 0) {
      indent(depth + 1);
      out_ << '<' << placeholder_for(node) << "/>\n";  // no name: BehaviorTree.CPP makes its path unique
    }
    return true;
  }

  void leave(const Node& node, int depth) override {
    if (node.kind() == NodeKind::Action || node.kind() == NodeKind::Condition) return;
    indent(depth);
    out_ << "</" << node.type_id() << ">\n";
  }

  void indent(int depth) {
    for (int i = 0; i < depth + 2; ++i) out_ << "  ";
  }

 private:
  void record_model(const Node& node) {
    const std::string_view id = node.type_id();
    auto it = model_.find(id);
    if (it == model_.end()) {
      it = model_.emplace(std::string(id), ModelEntry{node.kind(), {}}).first;
      model_order_.emplace_back(id);
    } else if (it->second.kind != node.kind()) {
      throw rtamp::Error("cannot export behavior tree: type ID '" + std::string(id) + "' is used for both " +
                         std::string(to_string(it->second.kind)) + " and " +
                         std::string(to_string(node.kind())) + " nodes");
    }
    ModelEntry& e = it->second;
    ++e.instances;
    for (const Port& p : node.user_ports()) {
      std::size_t i = 0;
      while (i < e.ports.size() && e.ports[i].name != p.name) ++i;
      if (i == e.ports.size()) {
        e.ports.push_back(Port{p.name, {}, p.description});
        e.port_uses.push_back(0);
      }
      ++e.port_uses[i];
    }
  }

  std::ostringstream& out_;
  const XmlOptions& opt_;
  std::map<std::string, ModelEntry, std::less<>>& model_;
  std::vector<std::string>& model_order_;
  std::vector<Port> ports_;
  NodeId preorder_ = 0;  // stands in for the id of a detached node
};

std::string export_xml(const Node* root, const XmlOptions& opt) {
  if (opt.tree_id.empty() || opt.tree_id == "root" || opt.tree_id == "Root") {
    throw rtamp::Error("cannot export behavior tree: tree ID '" + opt.tree_id +
                       "' is empty or reserved by BehaviorTree.CPP");
  }
  std::ostringstream out;
  std::map<std::string, ModelEntry, std::less<>> model;
  std::vector<std::string> order;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  if (opt.unique_names) out << "<!-- " << kUniqueNamesMarker << " -->\n";
  out << "<root BTCPP_format=\"4\" main_tree_to_execute=\"" << xml_escape(opt.tree_id) << "\">\n";
  out << "  <BehaviorTree ID=\"" << xml_escape(opt.tree_id) << "\">\n";
  if (root != nullptr) {
    XmlWriter writer(out, opt, model, order);
    accept(*root, writer);
  } else {
    out << "    <AlwaysFailure name=\"empty tree\"/>\n";
  }
  out << "  </BehaviorTree>\n";
  if (opt.include_model) {
    out << "  <TreeNodesModel>\n";
    for (const std::string& id : order) {
      const ModelEntry& e = model.find(id)->second;
      out << "    <" << to_string(e.kind) << " ID=\"" << id << '"';
      if (e.ports.empty()) {
        out << "/>\n";
        continue;
      }
      out << ">\n";
      for (std::size_t i = 0; i < e.ports.size(); ++i) {
        const Port& p = e.ports[i];
        out << "      <input_port name=\"" << p.name << "\" type=\"std::string\"";
        // A port some instance lacks gets a default, so the instance passes the schema.
        if (e.port_uses[i] < e.instances) out << " default=\"\"";
        if (p.description.empty()) {
          out << "/>\n";
        } else {
          out << '>' << xml_escape(p.description) << "</input_port>\n";
        }
      }
      out << "    </" << to_string(e.kind) << ">\n";
    }
    out << "  </TreeNodesModel>\n";
  }
  out << "</root>\n";
  return out.str();
}

}  // namespace

std::string to_btcpp_xml(const Tree& tree, const XmlOptions& options) {
  return export_xml(tree.root(), options);
}
std::string to_btcpp_xml(const Node& root, const XmlOptions& options) { return export_xml(&root, options); }

}  // namespace rtamp::bt
