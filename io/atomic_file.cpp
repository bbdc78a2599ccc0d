#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace granmc {

void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& what) {
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  int fd = -1;
  auto fail = [&](const std::string& step) {
    const std::string reason = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + what + " '" + path + "': " + step + " (" + reason + ")");
  };
  fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create '" + temporary + "'");
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("cannot write '" + temporary + "'");
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot flush '" + temporary + "' to the disk");
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) fail("cannot close '" + temporary + "'");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("cannot rename '" + temporary + "' to it");
}

}  // namespace granmc
