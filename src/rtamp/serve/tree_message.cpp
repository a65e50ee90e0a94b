#include "rtamp/serve/tree_message.hpp"

#include <string>
#include <vector>

#include "rtamp/util/json_text.hpp"

namespace rtamp::serve {

namespace {

const char* status_name(bt::Status s) {
  switch (s) {
    case bt::Status::Running: return "RUNNING";
    case bt::Status::Success: return "SUCCESS";
    case bt::Status::Failure: return "FAILURE";
    case bt::Status::Invalid: break;
  }
  return "IDLE";
}

char status_char(bt::Status s) {
  switch (s) {
    case bt::Status::Running: return 'R';
    case bt::Status::Success: return 'S';
    case bt::Status::Failure: return 'F';
    case bt::Status::Invalid: break;
  }
  return 'I';
}

class NodeLister : public bt::Visitor {
 public:
  NodeLister(std::string* nodes, std::string* statuses) : nodes_(nodes), statuses_(statuses) {}
  bool enter(const bt::Node& n, int depth) override {
    const int id = next_++;
    stack_.resize(static_cast<std::size_t>(depth));
    const int parent = stack_.empty() ? -1 : stack_.back();
    stack_.push_back(id);
    if (statuses_) *statuses_ += status_char(n.status());
    if (nodes_) {
      std::string& o = *nodes_;
      o += id ? ",{\"id\":" : "{\"id\":";
      o += std::to_string(id);
      o += ",\"parent\":";
      o += std::to_string(parent);
      o += ",\"name\":";
      json_text::append_string(o, n.name());
      o += ",\"kind\":";
      json_text::append_string(o, n.type_id());
      o += ",\"category\":";
      json_text::append_string(o, bt::to_string(n.kind()));
      o += ",\"status\":\"";
      o += status_name(n.status());
      o += "\"}";
    }
    return true;
  }

 private:
  std::string* nodes_;
  std::string* statuses_;
  std::vector<int> stack_;
  int next_ = 0;
};

}  // namespace

const char* status_name(char status) {
  switch (status) {
    case 'R': return status_name(bt::Status::Running);
    case 'S': return status_name(bt::Status::Success);
    case 'F': return status_name(bt::Status::Failure);
    default: return status_name(bt::Status::Invalid);
  }
}

std::string tree_message(double t, const bt::Tree& tree) {
  std::string out = "{\"type\":\"tree\",\"t\":";
  json_text::append_number(out, t);
  out += ",\"nodes\":[";
  if (tree.root()) {
    NodeLister l(&out, nullptr);
    bt::accept(*tree.root(), l);
  }
  out += "]}";
  return out;
}

std::string status_string(const bt::Tree& tree) {
  std::string s;
  if (tree.root()) {
    NodeLister l(nullptr, &s);
    bt::accept(*tree.root(), l);
  }
  return s;
}

std::string status_message(double t, const std::string& statuses) {
  std::string out = "{\"type\":\"status\",\"t\":";
  json_text::append_number(out, t);
  out += ",\"s\":\"";
  out += statuses;  // one of I R S F a node
  out += "\"}";
  return out;
}

}  // namespace rtamp::serve
