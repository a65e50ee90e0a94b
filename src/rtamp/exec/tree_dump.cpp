#include "rtamp/exec/tree_dump.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "rtamp/bt/xml_export.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::exec {

TreeDump::TreeDump(std::string dir) : dir_(std::move(dir)) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) throw Error("cannot create the tree directory '" + dir_ + "'");
  const std::regex ours(R"(tree_\d+\.xml)");
  for (const auto& e : fs::directory_iterator(dir_, ec))
    if (e.is_regular_file() && std::regex_match(e.path().filename().string(), ours)) fs::remove(e.path(), ec);
  const fs::path probe = fs::path(dir_) / ".rtamp-write-test";
  if (!std::ofstream(probe)) throw Error("cannot write into the tree directory '" + dir_ + "'");
  fs::remove(probe, ec);
}

void TreeDump::on_tree_change(double, const ReconfigurationReport& r, const PlanTree& tree, bool) {
  if (!r.applied) return;
  char name[64];
  std::snprintf(name, sizeof name, "/tree_%03d.xml", files_++);
  std::ofstream(dir_ + name) << bt::to_btcpp_xml(tree.tree());
}

}  // namespace rtamp::exec
