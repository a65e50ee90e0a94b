// A lasso found on canonical product states (task::System::set_symmetry),
// replayed as a Plan on the concrete states of the TS, from its initial state.
// A move of a member of a symmetry group at location a becomes the move of the
// lowest-numbered member of that group that is at a in the concrete state;
// every other step is taken as it is. Costs, labels and automaton states are
// the graph's (invariant under permuting a group, so the concrete plan costs
// what the canonical one does).
#pragma once

#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/plan/lasso_search.hpp"

namespace rtamp::plan {

Plan replay_lasso(const ProductGraph& g, const LassoResult& r);

}  // namespace rtamp::plan
