#include "rtamp/plan/algorithm.hpp"

namespace rtamp::plan {

const char* to_string(Algorithm a) {
  switch (a) {
    case Algorithm::Dijkstra: return "dijkstra";
    case Algorithm::AStar: return "astar";
    case Algorithm::AStarExperience: return "astar-exp";
  }
  return "?";
}

const NameTable<GraphConstruction>& graph_constructions() {
  static const NameTable<GraphConstruction> t = {
      {"partial", GraphConstruction::Partial, "product successors built as the search expands them (the paper's)"},
      {"full", GraphConstruction::Full, "the whole product built first (the baseline)"},
  };
  return t;
}

const char* to_string(GraphConstruction g) { return name_of(graph_constructions(), g); }

}  // namespace rtamp::plan
