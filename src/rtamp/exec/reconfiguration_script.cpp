#include "rtamp/exec/reconfiguration_script.hpp"

namespace rtamp::exec {

std::vector<Edit> reconfiguration_script(const std::vector<std::string>& subtree_actions,
                                         const std::vector<std::string>& plan_actions) {
  std::vector<std::string> cur = subtree_actions;  // the sequence as edits are applied
  std::vector<Edit> script;
  const std::size_t n = plan_actions.size();
  for (std::size_t i = 1; i <= n; ++i) {
    const std::string& want = plan_actions[n - i];
    if (cur.size() >= i) {
      const std::size_t pos = cur.size() - i;
      if (cur[pos] == want) {
        script.push_back({Edit::Kind::Update, pos, n - i});
        continue;
      }
      // Last earlier occurrence of `want` in cur[0, pos).
      std::size_t j = pos;
      while (j > 0 && cur[j - 1] != want) --j;
      if (j > 0) {
        const std::size_t keep = j - 1;  // index of the occurrence
        for (std::size_t k = pos; k > keep; --k) {
          script.push_back({Edit::Kind::Remove, k, 0});
          cur.erase(cur.begin() + static_cast<std::ptrdiff_t>(k));
        }
        script.push_back({Edit::Kind::Update, keep, n - i});
        continue;
      }
    }
    const std::size_t at = cur.size() - (i - 1);  // before the aligned suffix of length i-1
    script.push_back({Edit::Kind::Insert, at, n - i});
    cur.insert(cur.begin() + static_cast<std::ptrdiff_t>(at), want);
  }
  while (cur.size() > n) {
    script.push_back({Edit::Kind::Remove, 0, 0});
    cur.erase(cur.begin());
  }
  return script;
}

std::vector<std::string> apply_script(std::vector<std::string> seq, const std::vector<std::string>& plan,
                                      const std::vector<Edit>& script) {
  for (const Edit& e : script) {
    switch (e.kind) {
      case Edit::Kind::Update: seq.at(e.position) = plan.at(e.plan_index); break;
      case Edit::Kind::Insert:
        seq.insert(seq.begin() + static_cast<std::ptrdiff_t>(e.position), plan.at(e.plan_index));
        break;
      case Edit::Kind::Remove: seq.erase(seq.begin() + static_cast<std::ptrdiff_t>(e.position)); break;
    }
  }
  return seq;
}

std::size_t structural_changes(const std::vector<Edit>& script) {
  std::size_t n = 0;
  for (const Edit& e : script) n += e.kind != Edit::Kind::Update;
  return n;
}

}  // namespace rtamp::exec
