// The page's files that `rtamp serve` may send (docs/serve.md "Security"): a
// request path names a regular file under the web root, `index.html` for a
// directory. The path may not have `.` or `..` parts, a backslash or a NUL;
// the file is resolved (every symlink followed, fs::canonical) when it is
// asked for and must then still lie inside the web root, itself resolved
// when the server starts: a symlink in the root that leads out of it is
// refused, one that stays inside is served.
#pragma once

#include <string>

namespace rtamp::serve {

class WebRoot {
 public:
  // `dir` may be "" or missing: no page, every lookup fails.
  explicit WebRoot(const std::string& dir);

  bool has_page() const { return page_; }  // index.html is there

  struct Lookup {
    std::string path;    // the resolved file to send ("" when refused)
    bool outside = false;  // refused because it resolves outside the root
  };
  // `target`: the request target ("/assets/main.js?v=2"; the query is ignored).
  Lookup find(std::string target) const;

 private:
  std::string root_;  // canonical; "" without a root
  bool page_ = false;
};

}  // namespace rtamp::serve
