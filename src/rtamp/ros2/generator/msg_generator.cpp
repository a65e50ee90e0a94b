// The build-time generator of rtamp's ROS 2 messages: reads ROS 2 `.msg` files
// (src/rtamp/ros2/msg/PACKAGE/TYPE.msg, the ROS 2 interface language: fields,
// constants, default values, arrays T[], T[N], T[<=N], bounded strings) and
// writes one C++ header with, per message, in dependency order:
//   - a struct in namespace rtamp::ros2::PACKAGE with the fields (defaults as in
//     the .msg, else zero) and the constants as static constexpr members;
//   - `ros2_name` ("PACKAGE/msg/TYPE") and `ros2msg()`: the MCAP ros2msg schema
//     text, the .msg file as it is, then each dependency once (depth first, in
//     the order first used) after a line of 80 '=' and a line "MSG: PACKAGE/TYPE";
//   - `write(CdrWriter&, const T&)`: the CDR encoding of the fields in order
//     (cdr_writer.hpp has the alignment rules).
// With `--idl FILE` it also writes the same messages as OMG IDL in one file, in
// dependency order, named as ROS 2's rmw_cyclonedds names them on the wire
// (module PACKAGE::msg::dds_, struct TYPE_; constants in TYPE_Constants), for
// Cyclone DDS's idlc. One definition (the .msg file) is the struct, the encoder,
// the schema and the DDS type.
// Bad input (an unknown type, a malformed line, a cycle, wstring): one line
// "FILE:LINE: what" on stderr and exit 2, and no output file.
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Failure {
  std::string what;
};

struct Field {
  std::string base;      // primitive, or "pkg/Type"
  bool primitive = false;
  int array = 0;         // 0 scalar, 1 unbounded sequence, 2 fixed array, 3 bounded sequence
  std::size_t bound = 0; // array length or bound
  std::size_t string_bound = 0;
  std::string name, value;  // value: the default (field) or the value (constant)
  bool constant = false;
  int line = 0;
};

struct Message {
  std::string package, type, file, text;
  std::vector<Field> fields;  // constants too
  std::string full() const { return package + "/" + type; }
};

const std::map<std::string, std::string> kPrimitives = {
    {"bool", "bool"},           {"byte", "std::uint8_t"},   {"char", "std::uint8_t"},  {"float32", "float"},
    {"float64", "double"},      {"int8", "std::int8_t"},    {"uint8", "std::uint8_t"}, {"int16", "std::int16_t"},
    {"uint16", "std::uint16_t"}, {"int32", "std::int32_t"}, {"uint32", "std::uint32_t"}, {"int64", "std::int64_t"},
    {"uint64", "std::uint64_t"}, {"string", "std::string"}};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

std::size_t number(const std::string& s, const std::string& where) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) throw Failure{where + ": not a bound: '" + s + "'"};
  return std::stoul(s);
}

Message parse(const std::string& path) {
  Message m;
  {
    const auto slash = path.find_last_of('/');
    const std::string file = path.substr(slash == std::string::npos ? 0 : slash + 1);
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash);
    const auto up = dir.find_last_of('/');
    m.package = dir.substr(up == std::string::npos ? 0 : up + 1);
    if (file.size() < 5 || file.substr(file.size() - 4) != ".msg") throw Failure{path + ": not a .msg file"};
    m.type = file.substr(0, file.size() - 4);
    m.file = path;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Failure{path + ": cannot read it"};
  std::stringstream ss;
  ss << in.rdbuf();
  m.text = ss.str();
  std::istringstream lines(m.text);
  std::string raw;
  int n = 0;
  std::set<std::string> names;
  while (std::getline(lines, raw)) {
    ++n;
    const std::string where = path + ":" + std::to_string(n);
    std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    Field f;
    f.line = n;
    const auto space = line.find_first_of(" \t");
    if (space == std::string::npos) throw Failure{where + ": a field needs a type and a name"};
    std::string type = line.substr(0, space);
    std::string rest = trim(line.substr(space));
    // A string constant's value is the rest of the line; anything else ends at '#'.
    const auto eq = rest.find('=');
    const auto hash = rest.find('#');
    const bool constant = eq != std::string::npos && (hash == std::string::npos || eq < hash);
    if (!(constant && type == "string") && hash != std::string::npos) rest = trim(rest.substr(0, hash));
    if (constant) {
      f.constant = true;
      f.name = trim(rest.substr(0, eq));
      f.value = trim(rest.substr(eq + 1));
      if (f.value.empty()) throw Failure{where + ": constant " + f.name + " without a value"};
    } else {
      const auto sp = rest.find_first_of(" \t");
      f.name = rest.substr(0, sp);
      if (sp != std::string::npos) f.value = trim(rest.substr(sp));
    }
    if (!is_name(f.name)) throw Failure{where + ": not a field name: '" + f.name + "'"};
    if (!names.insert(f.name).second) throw Failure{where + ": " + f.name + " defined twice"};
    // Array suffix.
    if (const auto br = type.find('['); br != std::string::npos) {
      if (type.back() != ']') throw Failure{where + ": malformed array type '" + type + "'"};
      const std::string inside = type.substr(br + 1, type.size() - br - 2);
      type = type.substr(0, br);
      if (inside.empty()) {
        f.array = 1;
      } else if (inside.rfind("<=", 0) == 0) {
        f.array = 3;
        f.bound = number(inside.substr(2), where);
      } else {
        f.array = 2;
        f.bound = number(inside, where);
      }
    }
    if (const auto b = type.find("<="); b != std::string::npos) {
      f.string_bound = number(type.substr(b + 2), where);
      type = type.substr(0, b);
      if (type != "string") throw Failure{where + ": only strings have a bound: '" + type + "'"};
    }
    if (type == "wstring") throw Failure{where + ": wstring is not supported"};
    if (kPrimitives.count(type)) {
      f.primitive = true;
      f.base = type;
    } else {
      const auto s = type.find('/');
      f.base = s == std::string::npos ? m.package + "/" + type : type;
      const std::string pkg = f.base.substr(0, f.base.find('/')), t = f.base.substr(f.base.find('/') + 1);
      if (!is_name(pkg) || !is_name(t)) throw Failure{where + ": not a type: '" + type + "'"};
    }
    if (f.constant && (!f.primitive || f.array)) throw Failure{where + ": a constant must be of a primitive type"};
    m.fields.push_back(std::move(f));
  }
  return m;
}

std::string cpp_type(const Field& f) {
  std::string base;
  if (f.primitive) {
    base = kPrimitives.at(f.base);
  } else {
    const auto s = f.base.find('/');
    base = f.base.substr(0, s) + "::" + f.base.substr(s + 1);
  }
  if (f.array == 2) return "std::array<" + base + ", " + std::to_string(f.bound) + ">";
  if (f.array) return "std::vector<" + base + ">";
  return base;
}

std::string cpp_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o + "\"";
}

// A default or constant value as C++ (numbers and booleans as written, strings quoted).
std::string cpp_value(const Field& f, const std::string& v, const std::string& where) {
  if (f.base == "string") {
    if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
      return cpp_string(v.substr(1, v.size() - 2));
    return cpp_string(v);
  }
  if (f.base == "bool") {
    if (v == "true" || v == "True" || v == "1") return "true";
    if (v == "false" || v == "False" || v == "0") return "false";
    throw Failure{where + ": not a bool: '" + v + "'"};
  }
  if (v.empty() || v.find_first_not_of("0123456789+-.eE") != std::string::npos)
    throw Failure{where + ": not a number: '" + v + "'"};
  return v;
}

std::string default_of(const Field& f, const std::string& where) {
  if (f.value.empty()) return f.primitive && !f.array && f.base != "string" ? "{}" : "";
  if (!f.primitive) throw Failure{where + ": only primitive fields have defaults"};
  if (!f.array) return " = " + cpp_value(f, f.value, where);
  std::string v = f.value;
  if (v.size() < 2 || v.front() != '[' || v.back() != ']') throw Failure{where + ": an array default is [a, b, ...]"};
  std::string out = "{";
  std::stringstream items(v.substr(1, v.size() - 2));
  std::string item;
  bool first = true;
  while (std::getline(items, item, ',')) {
    out += first ? "" : ", ";
    first = false;
    out += cpp_value(f, trim(item), where);
  }
  return out + "}";
}

std::string raw_literal(const std::string& text) {
  std::string delim = "msg";
  while (text.find(")" + delim + "\"") != std::string::npos) delim += "x";
  return "R\"" + delim + "(" + text + ")" + delim + "\"";
}

std::string write_field(const Field& f) {
  const std::string x = "m." + f.name;
  const bool bytes = f.primitive && (f.base == "uint8" || f.base == "byte" || f.base == "char");
  std::string o;
  if (f.array == 3)
    o += "  if (" + x + ".size() > " + std::to_string(f.bound) + ") throw_bound(\"" + f.name + "\", " + x +
         ".size(), " + std::to_string(f.bound) + ");\n";
  if (f.string_bound && !f.array)
    o += "  if (" + x + ".size() > " + std::to_string(f.string_bound) + ") throw_bound(\"" + f.name + "\", " + x +
         ".size(), " + std::to_string(f.string_bound) + ");\n";
  if (f.array == 1 || f.array == 3) o += "  w.count(" + x + ".size());\n";
  if (!f.array) return o + (f.primitive ? "  w.put(" + x + ");\n" : "  write(w, " + x + ");\n");
  if (bytes) return o + "  w.put_bytes(" + x + ".data(), " + x + ".size());\n";
  return o + "  for (const auto& e : " + x + ") " + (f.primitive ? "w.put(e);\n" : "write(w, e);\n");
}

}  // namespace

// The IDL type of a field (the element type for arrays; `name` gets a fixed array's [N]).
std::string idl_type(const Field& f) {
  static const std::map<std::string, std::string> primitives = {
      {"bool", "boolean"}, {"byte", "octet"},   {"char", "uint8"},   {"float32", "float"},   {"float64", "double"},
      {"int8", "int8"},    {"uint8", "uint8"},  {"int16", "int16"},  {"uint16", "uint16"},   {"int32", "int32"},
      {"uint32", "uint32"}, {"int64", "int64"}, {"uint64", "uint64"}, {"string", "string"}};
  std::string base;
  if (f.primitive) {
    base = primitives.at(f.base);
    if (f.base == "string" && f.string_bound) base += "<" + std::to_string(f.string_bound) + ">";
  } else {
    const auto s = f.base.find('/');
    base = f.base.substr(0, s) + "::msg::dds_::" + f.base.substr(s + 1) + "_";
  }
  if (f.array == 1) return "sequence<" + base + ">";
  if (f.array == 3) return "sequence<" + base + ", " + std::to_string(f.bound) + ">";
  return base;
}

std::string idl(const std::vector<std::string>& order, const std::map<std::string, Message>& messages) {
  std::ostringstream o;
  o << "// Generated at build time by src/rtamp/ros2/generator/msg_generator.cpp from the .msg files\n"
       "// in src/rtamp/ros2/msg: do not edit. The DDS types of ROS 2 messages as rmw_cyclonedds\n"
       "// names them (PACKAGE::msg::dds_::TYPE_), in dependency order.\n";
  for (const auto& name : order) {
    const Message& m = messages.at(name);
    o << "\nmodule " << m.package << " { module msg { module dds_ {\n";
    bool constants = false;
    for (const Field& f : m.fields)
      if (f.constant) {
        if (!constants) o << "  module " << m.type << "_Constants {\n";
        constants = true;
        const std::string value = f.base == "bool" ? (cpp_value(f, f.value, m.file) == "true" ? "TRUE" : "FALSE")
                                                   : cpp_value(f, f.value, m.file);
        o << "    const " << idl_type(f) << " " << f.name << " = " << value << ";\n";
      }
    if (constants) o << "  };\n";
    o << "  @final struct " << m.type << "_ {\n";  // plain CDR, as ROS 2 sends it
    bool any = false;
    for (const Field& f : m.fields) {
      if (f.constant) continue;
      any = true;
      o << "    " << idl_type(f) << " " << f.name << (f.array == 2 ? "[" + std::to_string(f.bound) + "]" : "")
        << ";\n";
    }
    if (!any) o << "    uint8 structure_needs_at_least_one_member;\n";
    o << "  };\n}; }; };\n";
  }
  return o.str();
}

void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw Failure{path + ": cannot write it"};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Failure{path + ": cannot write it"};
}

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string idl_path;
  if (args.size() >= 2 && args[0] == "--idl") {
    idl_path = args[1];
    args.erase(args.begin(), args.begin() + 2);
  }
  if (args.size() < 2) {
    std::cerr << "usage: msg_generator [--idl OUT.idl] OUT.hpp PACKAGE/TYPE.msg...\n";
    return 2;
  }
  const std::string out_path = args[0];
  try {
    std::map<std::string, Message> messages;
    std::vector<std::string> inputs;
    for (std::size_t i = 1; i < args.size(); ++i) {
      Message m = parse(args[i]);
      const std::string name = m.full();
      if (messages.count(name)) throw Failure{m.file + ": " + name + " given twice"};
      inputs.push_back(name);
      messages.emplace(name, std::move(m));
    }
    // Dependency order (each message after what it uses), cycles refused.
    std::vector<std::string> order;
    std::map<std::string, int> mark;  // 1 visiting, 2 done
    std::function<void(const std::string&, const std::string&)> visit = [&](const std::string& name,
                                                                             const std::string& where) {
      const auto it = messages.find(name);
      if (it == messages.end()) throw Failure{where + ": unknown type " + name};
      if (mark[name] == 2) return;
      if (mark[name] == 1) throw Failure{where + ": " + name + " contains itself"};
      mark[name] = 1;
      for (const Field& f : it->second.fields)
        if (!f.primitive) visit(f.base, it->second.file + ":" + std::to_string(f.line));
      mark[name] = 2;
      order.push_back(name);
    };
    for (const auto& name : inputs) visit(name, messages.at(name).file);

    // Each message's dependencies, depth first in the order first used, each once.
    const auto dependencies = [&](const Message& root) {
      std::vector<std::string> deps;
      std::set<std::string> seen{root.full()};
      std::function<void(const Message&)> walk = [&](const Message& m) {
        for (const Field& f : m.fields)
          if (!f.primitive && seen.insert(f.base).second) {
            deps.push_back(f.base);
            walk(messages.at(f.base));
          }
      };
      walk(root);
      return deps;
    };

    std::ostringstream o;
    o << "// Generated at build time by src/rtamp/ros2/generator/msg_generator.cpp from the .msg files\n"
         "// in src/rtamp/ros2/msg (their README names the sources): do not edit. Per message: a struct\n"
         "// (fields with the .msg's defaults, constants), ros2_name, ros2msg() (the MCAP ros2msg schema)\n"
         "// and write() (its CDR encoding; rtamp::ros2::encode gives a whole message).\n"
         "#pragma once\n\n#include <array>\n#include <cstdint>\n#include <string>\n#include <string_view>\n"
         "#include <vector>\n\n#include \"rtamp/ros2/cdr_writer.hpp\"\n\nnamespace rtamp::ros2 {\n";
    for (const auto& name : order) {
      const Message& m = messages.at(name);
      std::string schema = m.text;
      if (!schema.empty() && schema.back() != '\n') schema += '\n';
      for (const auto& d : dependencies(m)) {
        const Message& dm = messages.at(d);
        schema += std::string(80, '=') + "\nMSG: " + dm.full() + "\n" + dm.text;
        if (!schema.empty() && schema.back() != '\n') schema += '\n';
      }
      o << "\nnamespace " << m.package << " {\n\n// " << m.package << "/msg/" << m.type << " (msg/" << m.package << "/"
        << m.type << ".msg)\nstruct " << m.type << " {\n  static constexpr std::string_view ros2_name = \"" << m.package << "/msg/"
        << m.type << "\";\n  static std::string_view ros2msg() {\n    return " << raw_literal(schema) << ";\n  }\n";
      for (const Field& f : m.fields) {
        const std::string where = m.file + ":" + std::to_string(f.line);
        if (f.constant) {
          const std::string t = f.base == "string" ? "std::string_view" : kPrimitives.at(f.base);
          o << "  static constexpr " << t << " " << f.name << " = " << cpp_value(f, f.value, where) << ";\n";
        }
      }
      for (const Field& f : m.fields) {
        if (f.constant) continue;
        const std::string where = m.file + ":" + std::to_string(f.line);
        o << "  " << cpp_type(f) << " " << f.name << default_of(f, where) << ";\n";
      }
      o << "};\n\ninline void write(CdrWriter& w, const " << m.type << "& m) {\n";
      bool any = false;
      for (const Field& f : m.fields)
        if (!f.constant) {
          o << write_field(f);
          any = true;
        }
      // ROS 2 gives a message without fields one uint8 ("structure_needs_at_least_one_member").
      if (!any) o << "  (void)m;\n  w.put(std::uint8_t{0});\n";
      o << "}\n\n}  // namespace " << m.package << "\n";
    }
    o << "\n}  // namespace rtamp::ros2\n";
    write_file(out_path, o.str());
    if (!idl_path.empty()) write_file(idl_path, idl(order, messages));
  } catch (const Failure& f) {
    std::cerr << "msg_generator: " << f.what << "\n";
    return 2;
  }
  return 0;
}
