#include "rtamp/plan/search_space.hpp"

#include <algorithm>

namespace rtamp::plan {

template <class T>
void SearchSpace::Slots<T>::grow(std::size_t cap, bool zero) {
  std::unique_ptr<T[]> q(new T[cap]);
  if (n) std::memcpy(q.get(), p.get(), n * sizeof(T));
  if (zero) std::memset(static_cast<void*>(q.get() + n), 0, (cap - n) * sizeof(T));
  p = std::move(q);
  n = cap;
}

void SearchSpace::ensure(std::size_t n) {
  if (stamp.size() >= n) return;
  const std::size_t cap = std::max<std::size_t>(n, stamp.size() * 2);
  g.grow(cap, false);
  m.grow(cap, false);
  h.grow(cap, false);
  parent.grow(cap, false);
  pedge.grow(cap, false);
  stamp.grow(cap, true);
  closed.grow(cap, false);
}

void SearchSpace::begin(std::size_t n) {
  ensure(std::max<std::size_t>(n, 256));
  if (++gen_ == 0) {  // wrapped: clear the stamps once
    std::fill(stamp.p.get(), stamp.p.get() + stamp.size(), 0u);
    gen_ = 1;
  }
  heap.clear();
}

void SearchSpace::push(SearchItem it) {
  heap.push_back(it);
  std::push_heap(heap.begin(), heap.end(), after);
}

SearchItem SearchSpace::pop() {
  std::pop_heap(heap.begin(), heap.end(), after);
  const SearchItem it = heap.back();
  heap.pop_back();
  return it;
}

std::size_t SearchSpace::bytes() const {
  return g.size() * 8 + m.size() * 4 + h.size() * 8 + parent.size() * 4 + pedge.size() * 4 + stamp.size() * 4 +
         closed.size() + heap.capacity() * sizeof(SearchItem);
}

}  // namespace rtamp::plan
