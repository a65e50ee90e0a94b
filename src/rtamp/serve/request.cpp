#include "rtamp/serve/request.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace rtamp::serve {

using nlohmann::json;

namespace {

bool kind_of(const std::string& s, world::Intervention::Kind& k) {
  using K = world::Intervention::Kind;
  if (s == "relocate") k = K::Relocate;
  else if (s == "add") k = K::Add;
  else if (s == "remove") k = K::Remove;
  else if (s == "add-container") k = K::AddContainer;
  else if (s == "remove-container") k = K::RemoveContainer;
  else if (s == "take-from-gripper") k = K::TakeFromGripper;
  else return false;
  return true;
}

// A string member: absent or null -> "", wrong type -> error.
bool string_field(const json& j, const char* key, std::string& out, std::string& error) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return true;
  if (!it->is_string()) {
    error = std::string("'") + key + "' must be a string";
    return false;
  }
  out = it->get<std::string>();
  return true;
}

}  // namespace

Request parse_request(const std::string& text) {
  Request r;
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    r.error = std::string("malformed JSON: ") + e.what();
    return r;
  }
  if (!j.is_object()) {
    r.error = "a request is one JSON object";
    return r;
  }
  if (auto it = j.find("id"); it != j.end()) {
    if (it->is_number() || it->is_string() || it->is_null())
      r.id = it->dump();
    else {
      r.error = "'id' must be a number or a string";
      return r;
    }
  }
  auto type = j.find("type");
  if (type == j.end() || !type->is_string()) {
    r.error = "a request needs a 'type' (\"intervene\", \"task\" or \"control\")";
    return r;
  }
  const std::string t = type->get<std::string>();
  if (t == "intervene") {
    std::string kind;
    if (!string_field(j, "kind", kind, r.error)) return r;
    if (!kind_of(kind, r.intervention.kind)) {
      r.error = "unknown intervention kind '" + kind +
                "' (expected one of: relocate, add, remove, add-container, remove-container, take-from-gripper)";
      return r;
    }
    if (!string_field(j, "subject", r.intervention.subject, r.error) ||
        !string_field(j, "class", r.intervention.cls, r.error) ||
        !string_field(j, "location", r.intervention.location, r.error))
      return r;
    if (auto p = j.find("position"); p != j.end() && !p->is_null()) {
      bool ok = p->is_array() && p->size() == 3;
      world::Vec3 v{0, 0, 0};
      for (std::size_t i = 0; ok && i < 3; ++i) {
        ok = (*p)[i].is_number() && std::isfinite((*p)[i].get<double>()) && std::abs((*p)[i].get<double>()) <= 1000;
        if (ok) v[i] = (*p)[i].get<double>();
      }
      if (!ok) {
        r.error = "'position' must be [x, y, z]: three finite numbers within ±1000 m";
        return r;
      }
      r.intervention.position = v;
    }
    r.type = Request::Type::Intervene;
    return r;
  }
  if (t == "task") {
    if (!string_field(j, "task", r.task, r.error)) return r;
    if (r.task.find_first_not_of(" \t\r\n") == std::string::npos) {
      r.error = "a task request needs a 'task' (an LTL formula)";
      return r;
    }
    r.type = Request::Type::Task;
    return r;
  }
  if (t == "control") {
    if (!string_field(j, "action", r.action, r.error)) return r;
    if (r.action != "pause" && r.action != "resume" && r.action != "step" && r.action != "speed" &&
        r.action != "seek") {
      r.error = "unknown control action '" + r.action + "' (expected one of: pause, resume, step, speed, seek)";
      return r;
    }
    if (auto v = j.find("value"); v != j.end() && !v->is_null()) {
      if (!v->is_number() || !std::isfinite(v->get<double>())) {
        r.error = "'value' must be a finite number";
        return r;
      }
      r.value = v->get<double>();
    }
    if ((r.action == "speed" || r.action == "seek") && !r.value) {
      r.error = "control '" + r.action + "' needs a 'value'";
      return r;
    }
    r.type = Request::Type::Control;
    return r;
  }
  r.error = "unknown request type '" + t + "' (expected \"intervene\", \"task\" or \"control\")";
  return r;
}

std::string reply_message(const std::string& id, bool ok, const std::string& error, const std::string& extra) {
  std::string s = "{\"type\":\"reply\",\"id\":" + id + ",\"ok\":" + (ok ? "true" : "false");
  if (!ok) s += ",\"error\":" + json(error).dump(-1, ' ', false, json::error_handler_t::replace);
  if (!extra.empty()) s += "," + extra;
  return s + "}";
}

}  // namespace rtamp::serve
