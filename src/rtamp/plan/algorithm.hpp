// The planner's named choices of search: the algorithm (Dijkstra, A*, A* with
// experience; their heuristics and factories are in plan/registry.hpp) and how
// the product graph is built (partial: as the search expands it, the paper's;
// full: all of it first, the baseline).
#pragma once

#include "rtamp/util/names_table.hpp"

namespace rtamp::plan {

enum class Algorithm { Dijkstra, AStar, AStarExperience };
enum class GraphConstruction { Partial, Full };
const char* to_string(Algorithm a);
const NameTable<GraphConstruction>& graph_constructions();  // partial full
const char* to_string(GraphConstruction g);

}  // namespace rtamp::plan
