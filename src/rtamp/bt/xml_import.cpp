#include "rtamp/bt/xml_import.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>

#include "rtamp/bt/composite.hpp"
#include "rtamp/bt/controls/chooser.hpp"
#include "rtamp/bt/controls/fallback.hpp"
#include "rtamp/bt/controls/parallel.hpp"
#include "rtamp/bt/controls/reactive_fallback.hpp"
#include "rtamp/bt/controls/reactive_sequence.hpp"
#include "rtamp/bt/controls/sequence.hpp"
#include "rtamp/bt/decorator.hpp"
#include "rtamp/bt/decorators/inverter.hpp"
#include "rtamp/bt/decorators/retry.hpp"
#include "rtamp/bt/decorators/state_update.hpp"
#include "rtamp/bt/decorators/timeout.hpp"
#include "rtamp/bt/xml_dom.hpp"
#include "rtamp/bt/xml_export.hpp"
#include "rtamp/bt/xml_schema.hpp"
#include "rtamp/util/text_file.hpp"

namespace rtamp::bt {

const std::string* NodeSpec::port(std::string_view port_name) const {
  for (const Port& p : ports) {
    if (p.name == port_name) return &p.value;
  }
  return nullptr;
}

NodeRegistry& NodeRegistry::add(std::string type_id, NodeFactory factory) {
  factories_[std::move(type_id)] = std::move(factory);
  return *this;
}

NodeRegistry& NodeRegistry::add_condition(std::string type_id, Condition::Predicate predicate) {
  return add(type_id, [type_id, predicate = std::move(predicate)](const NodeSpec& s) {
    return std::make_unique<Condition>(s.name, predicate, type_id);
  });
}

NodeRegistry& NodeRegistry::add_action(std::string type_id, Action::Callbacks callbacks) {
  return add(type_id, [type_id, callbacks = std::move(callbacks)](const NodeSpec& s) {
    return std::make_unique<Action>(s.name, callbacks, type_id);
  });
}

const NodeFactory* NodeRegistry::find(std::string_view type_id) const {
  auto it = factories_.find(type_id);
  return it == factories_.end() ? nullptr : &it->second;
}

namespace {

bool is_explicit_tag(std::string_view tag) {
  return tag == "Action" || tag == "Condition" || tag == "Control" || tag == "Decorator";
}

std::optional<NodeKind> kind_from_tag(std::string_view tag) {
  if (tag == "Action") return NodeKind::Action;
  if (tag == "Condition") return NodeKind::Condition;
  if (tag == "Control") return NodeKind::Control;
  if (tag == "Decorator") return NodeKind::Decorator;
  return std::nullopt;
}

std::string a_kind(NodeKind k) {
  return (k == NodeKind::Action ? "an " : "a ") + std::string(to_string(k));
}

// " #<digits>" at the end of an exported name.
std::string strip_id_suffix(const std::string& name) {
  std::size_t i = name.size();
  while (i > 0 && name[i - 1] >= '0' && name[i - 1] <= '9') --i;
  if (i == name.size() || i < 2 || name[i - 1] != '#' || name[i - 2] != ' ') return name;
  return name.substr(0, i - 2);
}

struct ModelInfo {
  NodeKind kind;
  std::map<std::string, std::string, std::less<>> descriptions;  // port name -> text
};

class Importer {
 public:
  Importer(const XmlDocument& doc, const NodeRegistry& registry, const XmlImportOptions& opt)
      : registry_(registry), file_(opt.file) {
    for (const std::string& c : doc.leading_comments) {
      if (c.find(kUniqueNamesMarker) != std::string::npos) strip_ = true;
    }
    const XmlElement& root = doc.root;
    if (root.tag != "root") fail(root, "expected <root BTCPP_format=\"4\">, not <" + root.tag + ">");
    if (const std::string* f = root.attribute("BTCPP_format"); f != nullptr && *f != "4") {
      fail(root, "BTCPP_format \"" + *f + "\" is not supported (only BehaviorTree.CPP v4 XML, BTCPP_format=\"4\")");
    }
    for (const XmlElement& e : root.children) {
      if (e.tag == "BehaviorTree") {
        const std::string* id = e.attribute("ID");
        if (id == nullptr || id->empty()) fail(e, "<BehaviorTree> has no ID");
        if (!trees_.emplace(*id, &e).second) fail(e, "two behavior trees with ID '" + *id + "'");
        tree_order_.push_back(*id);
      } else if (e.tag == "TreeNodesModel") {
        continue;  // read_models
      } else if (e.tag == "include") {
        fail(e, "<include> is not supported: put every tree in one file");
      } else {
        fail(e, "unexpected <" + e.tag + "> under <root> (expected BehaviorTree or TreeNodesModel)");
      }
    }
    read_models(doc);
    std::string id = opt.tree_id;
    if (id.empty()) {
      if (const std::string* main = root.attribute("main_tree_to_execute"); main != nullptr) id = *main;
    }
    if (id.empty()) {
      if (tree_order_.size() != 1) {
        fail(root, tree_order_.empty() ? "no <BehaviorTree> in the file"
                                       : "several behavior trees and no main_tree_to_execute: say which to build");
      }
      id = tree_order_.front();
    }
    main_ = id;
    if (trees_.find(id) == trees_.end()) fail(root, "no <BehaviorTree ID=\"" + id + "\"> in the file");
  }

  std::unique_ptr<Node> build() {
    const XmlElement& t = *trees_.at(main_);
    if (t.children.size() == 1 && t.children[0].tag == "AlwaysFailure" && t.children[0].children.empty()) {
      const std::string* n = t.children[0].attribute("name");
      if (n != nullptr && *n == "empty tree") return nullptr;
    }
    return tree(main_, t);
  }

 private:
  [[noreturn]] void fail(const XmlElement& e, const std::string& what) const {
    throw rtamp::Error(what, location_of(e, file_));
  }

  // The file's <TreeNodesModel>, read and checked once (xml_schema.hpp).
  void read_models(const XmlDocument& doc) {
    for (const NodeModel& m : read_tree_nodes_model(doc, file_)) {
      const auto kind = kind_from_tag(m.kind);
      if (!kind) continue;  // SubTree models describe trees, not nodes
      ModelInfo info{*kind, {}};
      for (const ModelPort& p : m.ports) info.descriptions[p.name] = p.description;
      models_[m.id] = std::move(info);
    }
  }

  // The single node element of a <BehaviorTree>.
  std::unique_ptr<Node> tree(const std::string& id, const XmlElement& t) {
    if (std::find(open_trees_.begin(), open_trees_.end(), id) != open_trees_.end()) {
      fail(t, "behavior tree '" + id + "' includes itself through <SubTree>");
    }
    if (t.children.size() != 1) fail(t, "<BehaviorTree ID=\"" + id + "\"> must hold exactly one node");
    open_trees_.push_back(id);
    auto root = node(t.children[0]);
    open_trees_.pop_back();
    return root;
  }

  static bool is_placeholder(const XmlElement& e) {
    return (e.tag == "AlwaysSuccess" || e.tag == "AlwaysFailure") && e.children.empty() &&
           (e.attribute("name") == nullptr || *e.attribute("name") == "(empty)");
  }

  std::string name_of(const XmlElement& e, const std::string& type_id) const {
    const std::string* n = e.attribute("name");
    if (n == nullptr) return type_id;
    return strip_ ? strip_id_suffix(*n) : *n;
  }

  // Attributes that are ports: everything but name/ID and metadata; script attributes are errors.
  std::vector<Port> ports_of(const XmlElement& e, bool explicit_form, const std::string& type_id) const {
    std::vector<Port> out;
    const ModelInfo* model = nullptr;
    if (auto it = models_.find(type_id); it != models_.end()) model = &it->second;
    for (const auto& [k, v] : e.attributes) {
      if (k == "name" || (explicit_form && k == "ID")) continue;
      if (k == "_uid" || k == "_fullpath" || k == "_description") continue;
      if (!k.empty() && k[0] == '_') {
        fail(e, "attribute '" + k + "' of <" + e.tag + ">: BehaviorTree.CPP scripts (pre/post conditions) are not supported by rtamp's engine");
      }
      if (v.size() >= 2 && v.front() == '{' && v.back() == '}') {
        fail(e, "port '" + k + "' of <" + e.tag + "> is a blackboard reference (" + v +
                    "); rtamp's engine takes port values as written");
      }
      std::string description;
      if (model != nullptr) {
        if (auto d = model->descriptions.find(k); d != model->descriptions.end()) description = d->second;
      }
      out.push_back(Port{k, v, description});
    }
    return out;
  }

  long integer(const XmlElement& e, const std::vector<Port>& ports, const char* port, std::optional<long> def,
               long lo) const {
    const Port* p = nullptr;
    for (const Port& q : ports) {
      if (q.name == port) p = &q;
    }
    if (p == nullptr) {
      if (def) return *def;
      fail(e, "<" + e.tag + "> needs the port " + port);
    }
    const char* s = p->value.c_str();
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(s, &end, 10);
    if (p->value.empty() || *end != '\0' || errno == ERANGE || v < lo || v > INT_MAX) {
      fail(e, std::string("port ") + port + " of <" + e.tag + ">: '" + p->value + "' is not an integer >= " +
                  std::to_string(lo));
    }
    return v;
  }

  void only_ports(const XmlElement& e, const std::vector<Port>& ports, std::initializer_list<std::string_view> allowed,
                  const std::string& type_id) const {
    for (const Port& p : ports) {
      if (std::find(allowed.begin(), allowed.end(), p.name) == allowed.end()) {
        fail(e, "<" + type_id + "> has no port '" + p.name + "'");
      }
    }
  }

  std::unique_ptr<Node> builtin(const XmlElement& e, const std::string& type_id, const std::string& name,
                                const std::vector<Port>& ports) const {
    if (type_id == "Sequence" || type_id == "ReactiveSequence" || type_id == "Fallback" ||
        type_id == "ReactiveFallback" || type_id == "Inverter") {
      only_ports(e, ports, {}, type_id);
      if (type_id == "Sequence") return std::make_unique<Sequence>(name);
      if (type_id == "ReactiveSequence") return std::make_unique<ReactiveSequence>(name);
      if (type_id == "Fallback") return std::make_unique<Fallback>(name);
      if (type_id == "ReactiveFallback") return std::make_unique<ReactiveFallback>(name);
      return std::make_unique<Inverter>(name);
    }
    if (type_id == "Parallel") {
      only_ports(e, ports, {"success_count", "failure_count"}, type_id);
      const long success = integer(e, ports, "success_count", -1, INT_MIN);
      const long failure = integer(e, ports, "failure_count", 1, INT_MIN);
      // BehaviorTree.CPP refuses a threshold written above the number of children (it could never be met).
      const long n = static_cast<long>(e.children.size());
      for (const auto& threshold : {std::pair{"success_count", success}, std::pair{"failure_count", failure}}) {
        const char* port = threshold.first;
        const long value = threshold.second;
        const bool written = std::any_of(ports.begin(), ports.end(), [&](const Port& p) { return p.name == port; });
        if (written && value > n) {
          fail(e, std::string("port ") + port + "=\"" + std::to_string(value) + "\" of <Parallel> is more than its " +
                      std::to_string(n) + (n == 1 ? " child" : " children") + " (the threshold could never be met)");
        }
      }
      return std::make_unique<Parallel>(name, static_cast<int>(success), static_cast<int>(failure));
    }
    if (type_id == "RetryUntilSuccessful") {
      only_ports(e, ports, {"num_attempts"}, type_id);
      const long n = integer(e, ports, "num_attempts", std::nullopt, -1);
      if (n == 0) fail(e, "port num_attempts of <RetryUntilSuccessful> must be positive or -1 (unlimited)");
      return std::make_unique<Retry>(name, static_cast<int>(n));
    }
    if (type_id == "Timeout") {
      only_ports(e, ports, {"msec"}, type_id);
      return std::make_unique<Timeout>(name, std::chrono::milliseconds(integer(e, ports, "msec", std::nullopt, 0)));
    }
    return nullptr;
  }

  std::unique_ptr<Node> node(const XmlElement& e) {
    const bool explicit_form = is_explicit_tag(e.tag);
    std::string type_id = e.tag;
    if (explicit_form) {
      const std::string* id = e.attribute("ID");
      if (id == nullptr || id->empty()) fail(e, "<" + e.tag + "> without ID");
      type_id = *id;
    }
    if (type_id == "SubTree") return subtree(e);
    const std::string name = name_of(e, type_id);
    std::vector<Port> ports = ports_of(e, explicit_form, type_id);
    std::unique_ptr<Node> n = builtin(e, type_id, name, ports);
    if (!n) n = custom(e, type_id, name, ports);
    const auto declared = explicit_form ? kind_from_tag(e.tag) : std::nullopt;
    if (declared && *declared != n->kind()) {
      fail(e, "<" + e.tag + " ID=\"" + type_id + "\"> builds " + a_kind(n->kind()) + " node");
    }
    if (auto it = models_.find(type_id); it != models_.end() && it->second.kind != n->kind()) {
      fail(e, "'" + type_id + "' is declared as " + a_kind(it->second.kind) + " in <TreeNodesModel> but builds " +
                  a_kind(n->kind()) + " node");
    }
    children(e, *n);
    return n;
  }

  std::unique_ptr<Node> custom(const XmlElement& e, const std::string& type_id, const std::string& name,
                               const std::vector<Port>& ports) const {
    NodeSpec spec{type_id, name, ports, std::nullopt, location_of(e, file_)};
    if (auto it = models_.find(type_id); it != models_.end()) spec.declared_kind = it->second.kind;
    std::unique_ptr<Node> n;
    try {
      if (const NodeFactory* f = registry_.find(type_id)) {
        n = (*f)(spec);
        if (!n) fail(e, "the factory for '" + type_id + "' returned no node");
      } else if (type_id == "Chooser") {
        n = std::make_unique<Chooser>(name);
      } else if (type_id == "StateUpdate") {
        n = std::make_unique<StateUpdate>(name, StateUpdate::Update{});
      } else {
        fail(e, "unknown node '" + type_id + "': not a node of rtamp's engine and not in the registry" +
                    (spec.declared_kind ? " (declared as " + a_kind(*spec.declared_kind) + ")" : ""));
      }
      n->set_name(name);
      if (!n->btcpp_builtin()) {
        for (const Port& p : ports) n->set_port(p.name, p.value, p.description);
      }
    } catch (const rtamp::Error& err) {
      if (err.where().line > 0) throw;
      fail(e, err.message());
    }
    return n;
  }

  void children(const XmlElement& e, Node& n) {
    std::vector<const XmlElement*> kids;
    for (const XmlElement& c : e.children) kids.push_back(&c);
    if (n.kind() == NodeKind::Control && kids.size() == 1 && is_placeholder(*kids[0])) kids.clear();
    switch (n.kind()) {
      case NodeKind::Action:
      case NodeKind::Condition:
        if (!kids.empty()) fail(*kids[0], "<" + e.tag + "> is a leaf (" + std::string(to_string(n.kind())) + ") and cannot have children");
        return;
      case NodeKind::Decorator: {
        if (kids.size() != 1) fail(e, "decorator <" + e.tag + "> needs exactly one child, not " + std::to_string(kids.size()));
        auto* d = dynamic_cast<Decorator*>(&n);
        if (d == nullptr) fail(e, "<" + e.tag + "> is a decorator but not a bt::Decorator");
        d->set_child(node(*kids[0]));
        return;
      }
      case NodeKind::Control: {
        auto* c = dynamic_cast<Composite*>(&n);
        if (c == nullptr) fail(e, "<" + e.tag + "> is a control node but not a bt::Composite");
        for (const XmlElement* k : kids) c->add(node(*k));
        return;
      }
    }
  }

  std::unique_ptr<Node> subtree(const XmlElement& e) {
    const std::string* id = e.attribute("ID");
    if (id == nullptr || id->empty()) fail(e, "<SubTree> without ID");
    for (const auto& [k, v] : e.attributes) {
      if (k != "ID" && k != "name" && k != "_autoremap" && k != "_uid" && k != "_fullpath") {
        fail(e, "<SubTree ID=\"" + *id + "\">: port remapping ('" + k + "') is not supported (rtamp inlines subtrees)");
      }
    }
    if (!e.children.empty()) fail(e, "<SubTree> cannot have children");
    auto it = trees_.find(*id);
    if (it == trees_.end()) fail(e, "<SubTree ID=\"" + *id + "\">: no behavior tree with that ID in the file");
    return tree(*id, *it->second);
  }

  const NodeRegistry& registry_;
  std::string file_;
  bool strip_ = false;
  std::map<std::string, const XmlElement*, std::less<>> trees_;
  std::vector<std::string> tree_order_;
  std::map<std::string, ModelInfo, std::less<>> models_;
  std::vector<std::string> open_trees_;
  std::string main_;
};

}  // namespace

std::unique_ptr<Node> from_btcpp_xml(std::string_view xml, const NodeRegistry& registry,
                                     const XmlImportOptions& options) {
  const XmlDocument doc = parse_xml(xml, options.file);
  return Importer(doc, registry, options).build();
}

std::unique_ptr<Node> load_btcpp_xml(const std::string& path, const NodeRegistry& registry, XmlImportOptions options) {
  const std::string text = read_text_file(path, "the behavior-tree file");
  if (options.file.empty()) options.file = path;
  return from_btcpp_xml(text, registry, options);
}

}  // namespace rtamp::bt
