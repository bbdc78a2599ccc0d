#pragma once
// The collective operations a system spread over several processes needs (one large replica over MPI
// ranks, kernel/schemes/rank_wave_backend.hpp; docs/developer-guide/scaling.md). The kernel sees only this interface:
// the MPI implementation lives in drivers/ (drivers/mpi_replicas.cpp), and SingleRank is the one-process case.
#include <cstddef>
#include <span>
#include <vector>

namespace granmc {

class Ranks {
 public:
  virtual ~Ranks() = default;
  [[nodiscard]] virtual int rank() const noexcept = 0;
  [[nodiscard]] virtual int size() const noexcept = 0;
  /// Element-wise sum over the ranks, the result on every rank. The callers give every element one
  /// nonzero contribution at most, or whole numbers (histogram counts), so the sum is exact and
  /// independent of the reduction order.
  virtual void sum(std::span<double> values) const = 0;
  /// The largest value over the ranks, on every rank.
  [[nodiscard]] virtual double max(double value) const = 0;
  /// Sends send[r] to rank r and receives into receive[r] what rank r sent here. Both sides know the
  /// sizes: receive[r] arrives sized.
  virtual void exchange(const std::vector<std::vector<double>>& send,
                        std::vector<std::vector<double>>& receive) const = 0;
};

/// One process: every collective is the identity.
class SingleRank final : public Ranks {
 public:
  [[nodiscard]] int rank() const noexcept override { return 0; }
  [[nodiscard]] int size() const noexcept override { return 1; }
  void sum(std::span<double>) const override {}
  [[nodiscard]] double max(double value) const override { return value; }
  void exchange(const std::vector<std::vector<double>>& send,
                std::vector<std::vector<double>>& receive) const override {
    receive = send;
  }
};

}  // namespace granmc
