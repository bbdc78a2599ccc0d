#pragma once
// A set of record addresses (particles, by SpeciesStore::Particle::address), exact, for the few particles a
// thread's collision round holds back (schemes/concurrent_rounds.hpp): open addressing, grown when half
// full, emptied in the time of its entries.
#include <cstdint>
#include <vector>

namespace granmc {

class AddressSet {
 public:
  [[nodiscard]] bool contains(const void* a) const noexcept {
    for (std::size_t s = slot(a);; s = (s + 1) & mask()) {
      if (table_[s] == a) return true;
      if (table_[s] == nullptr) return false;
    }
  }

  void insert(const void* a) {
    if (2 * (filled_.size() + 1) > table_.size()) grow();
    place(a);
  }

  [[nodiscard]] bool empty() const noexcept { return filled_.empty(); }

  void clear() noexcept {
    for (std::size_t s : filled_) table_[s] = nullptr;
    filled_.clear();
  }

 private:
  std::size_t mask() const noexcept { return table_.size() - 1; }
  std::size_t slot(const void* a) const noexcept {  // Fibonacci hashing of the record address
    return static_cast<std::size_t>((reinterpret_cast<std::uintptr_t>(a) * 0x9E3779B97F4A7C15ull) >> 20) & mask();
  }
  void place(const void* a) {
    std::size_t s = slot(a);
    for (; table_[s] != nullptr; s = (s + 1) & mask())
      if (table_[s] == a) return;
    table_[s] = a;
    filled_.push_back(s);
  }
  void grow() {
    std::vector<const void*> old;
    for (std::size_t s : filled_) old.push_back(table_[s]);
    table_.assign(2 * table_.size(), nullptr);
    filled_.clear();
    for (const void* a : old) place(a);
  }

  std::vector<const void*> table_ = std::vector<const void*>(256, nullptr);
  std::vector<std::size_t> filled_;  // the occupied slots
};

}  // namespace granmc
