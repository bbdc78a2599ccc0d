#pragma once
#include <functional>

namespace granmc {

struct RunOptions {
  int threads = 0;                     // OpenMP threads for the replicas; 0: the OpenMP default
  std::function<void()> on_sample;     // called after each observation of each replica, from any thread
};

}  // namespace granmc
