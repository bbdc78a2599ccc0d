#include "io/build_id.hpp"

#include "granmc/build_id.hpp"

namespace granmc {

const char* build_id() noexcept { return generated::build_id; }

}  // namespace granmc
