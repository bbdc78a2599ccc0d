#pragma once
// Which build of granmc this is: its version and the commit it was built from ("0.1.0+0123456789ab",
// "-dirty" when the tracked files differed from the commit, "+unknown commit" outside a git checkout).
// `granmc --version` prints it, every HDF5 file and summary records it (`build`), and a sweep reruns the
// scenes that another build made (drivers/sweep.cpp).

namespace granmc {

const char* build_id() noexcept;

}  // namespace granmc
