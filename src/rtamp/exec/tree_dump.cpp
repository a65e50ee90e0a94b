#include "rtamp/exec/tree_dump.hpp"

#include "rtamp/util/output_file.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "rtamp/bt/xml_export.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::exec {

TreeDump::TreeDump(std::string dir) : dir_(std::move(dir)) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) throw Error("cannot create the tree directory '" + dir_ + "'");
  auto ours = [](const std::string& n) {  // tree_<digits>.xml
    if (n.size() < 10 || n.rfind("tree_", 0) != 0 || n.substr(n.size() - 4) != ".xml") return false;
    return std::all_of(n.begin() + 5, n.end() - 4, [](char c) { return c >= '0' && c <= '9'; });
  };
  for (const auto& e : fs::directory_iterator(dir_, ec))
    if (e.is_regular_file() && ours(e.path().filename().string())) fs::remove(e.path(), ec);
  const fs::path probe = fs::path(dir_) / ".rtamp-write-test";
  if (!std::ofstream(probe)) throw Error("cannot write into the tree directory '" + dir_ + "'");
  fs::remove(probe, ec);
}

void TreeDump::on_tree_change(double, const ReconfigurationReport& r, const PlanTree& tree, bool) {
  if (!r.applied) return;
  char name[64];
  if (!lost_.empty()) return;
  std::snprintf(name, sizeof name, "/tree_%03d.xml", files_++);
  try {
    write_output_file(dir_ + name, "--trees", bt::to_btcpp_xml(tree.tree()));
  } catch (const OutputError& e) {
    lost_ = e.message();  // the episode goes on; close() reports it
  }
}

void TreeDump::close() const {
  if (!lost_.empty()) throw OutputError(lost_);
}

}  // namespace rtamp::exec
