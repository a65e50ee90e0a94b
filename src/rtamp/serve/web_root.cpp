#include "rtamp/serve/web_root.hpp"

#include <algorithm>
#include <filesystem>

namespace rtamp::serve {

namespace fs = std::filesystem;

namespace {

// Whether canonical `p` is `root` or lies under it (compared part by part).
bool inside(const fs::path& root, const fs::path& p) {
  const auto [r, q] = std::mismatch(root.begin(), root.end(), p.begin(), p.end());
  return r == root.end();
}

}  // namespace

WebRoot::WebRoot(const std::string& dir) {
  std::error_code ec;
  if (dir.empty()) return;
  const fs::path root = fs::canonical(dir, ec);
  if (ec || !fs::is_directory(root, ec)) return;
  root_ = root.string();
  page_ = !find("/").path.empty();
}

WebRoot::Lookup WebRoot::find(std::string target) const {
  if (root_.empty()) return {};
  if (auto q = target.find_first_of("?#"); q != std::string::npos) target.resize(q);
  if (target.empty() || target[0] != '/') return {};
  if (target.find('\\') != std::string::npos || target.find('\0') != std::string::npos) return {};
  for (const auto& part : fs::path(target).relative_path())
    if (part == ".." || part == ".") return {};
  const fs::path root(root_);
  std::error_code ec;
  fs::path p = fs::canonical(root / fs::path(target).relative_path(), ec);
  if (ec) return {};
  if (!inside(root, p)) return {"", true};
  if (fs::is_directory(p, ec)) {
    p = fs::canonical(p / "index.html", ec);
    if (ec) return {};
    if (!inside(root, p)) return {"", true};
  }
  if (!fs::is_regular_file(p, ec)) return {};
  return {p.string(), false};
}

}  // namespace rtamp::serve
