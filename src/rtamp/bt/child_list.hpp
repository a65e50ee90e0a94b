// rtamp::bt::ChildList — the children of a node: an owning array of Node
// pointers with room for two children inside the node itself (most composites
// of the paper's trees — Chooser, the pre/post Sequences — have one or two), so
// ticking them does not chase a separately allocated array. Larger lists move to
// the heap, doubling. The owning Node deletes the children (see ~Node).
// Invariant: data_ points to inline_ or to a heap array of cap_ entries.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>

namespace rtamp::bt {

class Node;

class ChildList {
 public:
  ChildList() = default;
  ~ChildList() {
    if (data_ != inline_) delete[] data_;
  }
  ChildList(const ChildList&) = delete;
  ChildList& operator=(const ChildList&) = delete;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Node* operator[](std::size_t i) const { return data_[i]; }
  Node* const* begin() const { return data_; }
  Node* const* end() const { return data_ + size_; }
  std::span<Node* const> span() const { return {data_, size_}; }

  void insert(std::size_t pos, Node* node) {
    if (size_ == cap_) grow();
    std::memmove(data_ + pos + 1, data_ + pos, (size_ - pos) * sizeof(Node*));
    data_[pos] = node;
    ++size_;
  }
  // Removes entry pos (does not delete the node).
  void erase(std::size_t pos) {
    std::memmove(data_ + pos, data_ + pos + 1, (size_ - pos - 1) * sizeof(Node*));
    --size_;
  }
  // Puts node at pos and returns the previous entry (not deleted).
  Node* exchange(std::size_t pos, Node* node) {
    Node* old = data_[pos];
    data_[pos] = node;
    return old;
  }

 private:
  void grow() {
    const std::uint32_t cap = cap_ * 2;
    Node** fresh = new Node*[cap];
    std::memcpy(fresh, data_, size_ * sizeof(Node*));
    if (data_ != inline_) delete[] data_;
    data_ = fresh;
    cap_ = cap;
  }

  Node** data_ = inline_;
  std::uint32_t size_ = 0;
  std::uint32_t cap_ = 2;
  Node* inline_[2] = {nullptr, nullptr};
};

}  // namespace rtamp::bt
