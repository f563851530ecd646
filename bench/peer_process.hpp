// A peer renderer in a child process: this benchmark binary started again with
// kPeerChildFlag, the environment the peer needs, and one end of a socket pair as descriptor
// kPeerChildFd. The two sides exchange text lines, one reply per request.
#pragma once

#include <sys/types.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace edgewise::bench {

inline constexpr std::string_view kPeerChildFlag = "--edgewise-draw-peer-child";
inline constexpr int kPeerChildFd = 3;

// One line over a connected socket, without its newline; nullopt when the other side is gone.
class LineChannel {
 public:
  explicit LineChannel(int fd) : fd_(fd) {}
  bool send(std::string_view line);
  std::optional<std::string> receive();
  int fd() const { return fd_; }

 private:
  int fd_;
  std::string buffered_;
};

class PeerProcess {
 public:
  // Variables to set (name, value) or, with no value, to remove from the child's environment.
  using EnvironmentChanges = std::vector<std::pair<std::string, std::optional<std::string>>>;

  // Starts this binary (/proc/self/exe) with kPeerChildFlag; nullptr with the reason in `error`.
  static std::unique_ptr<PeerProcess> start(const EnvironmentChanges& changes, std::string& error);
  // Closes the socket, which ends the child's loop, and waits for it.
  ~PeerProcess();
  PeerProcess(const PeerProcess&) = delete;
  PeerProcess& operator=(const PeerProcess&) = delete;

  // Sends `line` and waits for the reply; nullopt when the child has ended.
  std::optional<std::string> request(std::string_view line);
  // The first line the child sends by itself once it has started.
  std::optional<std::string> greeting() { return channel_.receive(); }

 private:
  PeerProcess(pid_t pid, int fd) : pid_(pid), channel_(fd) {}
  pid_t pid_;
  LineChannel channel_;
};

}  // namespace edgewise::bench
