// Tree dumps: an EpisodeObserver that writes the behavior tree as
// BehaviorTree.CPP v4 XML (Groot2 opens it) after every applied change, as
// DIR/tree_000.xml, tree_001.xml, ... The constructor creates DIR and removes
// tree_*.xml files an earlier run left there (so the files are this run's),
// and throws rtamp::Error if DIR cannot be created or written — before the
// episode starts. Each file is written as every output is
// (util/output_file.hpp); a file that could not be written stops the dumps,
// not the episode, and close() throws its rtamp::OutputError.
#pragma once

#include <string>

#include "rtamp/exec/episode_observer.hpp"

namespace rtamp::exec {

class TreeDump final : public EpisodeObserver {
 public:
  explicit TreeDump(std::string dir);
  void on_tree_change(double t, const ReconfigurationReport&, const PlanTree&, bool deferred) override;
  int files() const { return files_; }
  // Throws rtamp::OutputError if a tree file was lost.
  void close() const;

 private:
  std::string dir_;
  std::string lost_;  // why the first lost file was lost
  int files_ = 0;
};

}  // namespace rtamp::exec
