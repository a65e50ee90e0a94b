#include "rtamp/bt/text_render.hpp"

namespace rtamp::bt {

namespace {

class TextWriter : public Visitor {
 public:
  TextWriter(std::string& out, const TextOptions& opt) : out_(out), opt_(opt) {}
  bool enter(const Node& node, int depth) override {
    out_.append(static_cast<std::size_t>(depth) * 4, ' ');
    out_ += status_marker(node.status());
    out_ += ' ';
    out_ += node.type_id();
    if (node.name() != node.type_id()) {
      out_ += " \"";
      out_ += node.name();
      out_ += '"';
    }
    if (opt_.show_ids && node.id() != kNoId) {
      out_ += " #";
      out_ += std::to_string(node.id());
    }
    out_ += '\n';
    if (opt_.max_depth >= 0 && depth >= opt_.max_depth && node.child_count() > 0) {
      out_.append(static_cast<std::size_t>(depth + 1) * 4, ' ');
      out_ += "... (" + std::to_string(node.child_count()) + " children)\n";
      return false;
    }
    return true;
  }

 private:
  std::string& out_;
  const TextOptions& opt_;
};

}  // namespace

std::string to_text(const Node& root, const TextOptions& options) {
  std::string out;
  TextWriter w(out, options);
  accept(root, w);
  return out;
}

std::string to_text(const Tree& tree, const TextOptions& options) {
  if (tree.root() == nullptr) return "(empty tree)\n";
  return to_text(*tree.root(), options);
}

}  // namespace rtamp::bt
