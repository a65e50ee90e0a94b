#include "rtamp/bt/dot_export.hpp"

#include <sstream>
#include <vector>

namespace rtamp::bt {

namespace {

std::string dot_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

std::string_view shape_of(NodeKind kind) {
  switch (kind) {
    case NodeKind::Control:
      return "shape=box";
    case NodeKind::Decorator:
      return "shape=hexagon";
    case NodeKind::Condition:
      return "shape=ellipse";
    case NodeKind::Action:
      return "shape=box, style=\"rounded,filled\"";
  }
  return "shape=box";
}

std::string_view color_of(Status s) {
  switch (s) {
    case Status::Running:
      return "#fff3b0";
    case Status::Success:
      return "#c8f7c5";
    case Status::Failure:
      return "#f7c5c5";
    case Status::Invalid:
      return "#ffffff";
  }
  return "#ffffff";
}

class DotWriter : public Visitor {
 public:
  DotWriter(std::ostringstream& out, const DotOptions& opt) : out_(out), opt_(opt) {}

  bool enter(const Node& node, int /*depth*/) override {
    std::string key(1, 'n');
    if (node.id() != kNoId) {
      key += std::to_string(node.id());
    } else {
      key += 'x';  // detached: pre-order number
      key += std::to_string(++counter_);
    }
    out_ << "  " << key << " [label=\"" << dot_escape(node.type_id());
    if (node.name() != node.type_id()) out_ << "\\n" << dot_escape(node.name());
    if (opt_.show_ids && node.id() != kNoId) out_ << "\\n#" << node.id();
    out_ << "\", " << shape_of(node.kind());
    if (opt_.show_status) {
      if (node.kind() != NodeKind::Action) out_ << ", style=filled";
      out_ << ", fillcolor=\"" << color_of(node.status()) << '"';
    }
    out_ << "];\n";
    if (!stack_.empty()) out_ << "  " << stack_.back() << " -> " << key << ";\n";
    stack_.push_back(key);
    return true;
  }
  void leave(const Node&, int) override { stack_.pop_back(); }

 private:
  std::ostringstream& out_;
  const DotOptions& opt_;
  std::vector<std::string> stack_;
  unsigned counter_ = 0;
};

std::string export_dot(const Node* root, const DotOptions& opt) {
  std::ostringstream out;
  out << "digraph \"" << dot_escape(opt.graph_name) << "\" {\n";
  out << "  node [fontname=\"Helvetica\", fontsize=10];\n";
  if (root != nullptr) {
    DotWriter w(out, opt);
    accept(*root, w);
  }
  out << "}\n";
  return out.str();
}

}  // namespace

std::string to_dot(const Tree& tree, const DotOptions& options) { return export_dot(tree.root(), options); }
std::string to_dot(const Node& root, const DotOptions& options) { return export_dot(&root, options); }

}  // namespace rtamp::bt
