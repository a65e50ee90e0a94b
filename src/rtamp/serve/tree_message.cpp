#include "rtamp/serve/tree_message.hpp"

#include <vector>

#include <nlohmann/json.hpp>

namespace rtamp::serve {

using nlohmann::json;

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
  explicit NodeLister(json* nodes, std::string* statuses) : nodes_(nodes), statuses_(statuses) {}
  bool enter(const bt::Node& n, int depth) override {
    const int id = next_++;
    stack_.resize(static_cast<std::size_t>(depth));
    const int parent = stack_.empty() ? -1 : stack_.back();
    stack_.push_back(id);
    if (statuses_) *statuses_ += status_char(n.status());
    if (nodes_)
      nodes_->push_back({{"id", id},
                         {"parent", parent},
                         {"name", n.name()},
                         {"kind", std::string(n.type_id())},
                         {"category", std::string(bt::to_string(n.kind()))},
                         {"status", status_name(n.status())}});
    return true;
  }

 private:
  json* nodes_;
  std::string* statuses_;
  std::vector<int> stack_;
  int next_ = 0;
};

}  // namespace

std::string tree_message(double t, const bt::Tree& tree) {
  json nodes = json::array();
  if (tree.root()) {
    NodeLister l(&nodes, nullptr);
    bt::accept(*tree.root(), l);
  }
  return json{{"type", "tree"}, {"t", t}, {"nodes", nodes}}.dump(-1, ' ', false, json::error_handler_t::replace);
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
  return json{{"type", "status"}, {"t", t}, {"s", statuses}}.dump();
}

}  // namespace rtamp::serve
