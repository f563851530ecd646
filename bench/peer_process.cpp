#include "peer_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace edgewise::bench {

bool LineChannel::send(std::string_view line) {
  std::string message(line);
  message += '\n';
  for (std::size_t sent = 0; sent < message.size();) {
    // MSG_NOSIGNAL: a child that has ended gives an error here, not SIGPIPE.
    const ssize_t n = ::send(fd_, message.data() + sent, message.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += std::size_t(n);
  }
  return true;
}

std::optional<std::string> LineChannel::receive() {
  for (;;) {
    const std::size_t end = buffered_.find('\n');
    if (end != std::string::npos) {
      std::string line = buffered_.substr(0, end);
      buffered_.erase(0, end + 1);
      return line;
    }
    char chunk[4096];
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    buffered_.append(chunk, std::size_t(n));
  }
}

std::unique_ptr<PeerProcess> PeerProcess::start(const EnvironmentChanges& changes,
                                                std::string& error) {
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    error = std::string("socketpair: ") + std::strerror(errno);
    return nullptr;
  }
  // Above kPeerChildFd, so that the child's dup2 always copies it (and so clears close-on-exec).
  const int child_end = fcntl(ends[1], F_DUPFD_CLOEXEC, kPeerChildFd + 1);
  close(ends[1]);
  if (child_end < 0) {
    close(ends[0]);
    error = std::string("fcntl: ") + std::strerror(errno);
    return nullptr;
  }

  std::vector<std::string> variables;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string_view text(*entry);
    bool changed = false;
    for (const auto& [name, value] : changes)
      changed = changed || (text.size() > name.size() && text.substr(0, name.size()) == name &&
                            text[name.size()] == '=');
    if (!changed) variables.emplace_back(text);
  }
  for (const auto& [name, value] : changes) {
    if (value) variables.push_back(name + "=" + *value);
  }
  std::vector<char*> environment;
  for (std::string& variable : variables)
    environment.push_back(variable.data());
  environment.push_back(nullptr);

  // The running binary itself, even if its file has been replaced since it started.
  std::string program = "/proc/self/exe";
  std::string flag(kPeerChildFlag);
  char* arguments[] = {program.data(), flag.data(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, child_end, kPeerChildFd);
  pid_t pid = 0;
  const int failure =
      posix_spawn(&pid, program.c_str(), &actions, nullptr, arguments, environment.data());
  posix_spawn_file_actions_destroy(&actions);
  close(child_end);
  if (failure != 0) {
    close(ends[0]);
    error = std::string("starting the peer process: ") + std::strerror(failure);
    return nullptr;
  }
  return std::unique_ptr<PeerProcess>(new PeerProcess(pid, ends[0]));
}

PeerProcess::~PeerProcess() {
  close(channel_.fd());
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
}

std::optional<std::string> PeerProcess::request(std::string_view line) {
  if (!channel_.send(line)) return std::nullopt;
  return channel_.receive();
}

}  // namespace edgewise::bench
