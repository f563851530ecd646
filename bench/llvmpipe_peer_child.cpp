// The peer process's loop (peer_process.hpp): it greets with "ready <GL_RENDERER>" or
// "error <reason>", then answers
//   load <workload>  with "counts <covered> <written>" (draw_peer_workloads.hpp,
//                    LlvmpipePeer::count)
//   draw             with "seconds <wall> <cpu>", one draw's times (LlvmpipePeer::timed_draw)
// or "error <reason>", until the benchmark closes its end.
#include <cstdio>
#include <exception>
#include <string>

#include "llvmpipe_peer.hpp"
#include "peer_process.hpp"

namespace edgewise::bench {

int serve_llvmpipe_peer(int fd) {
  LineChannel channel(fd);
  std::string error;
  const std::unique_ptr<LlvmpipePeer> peer = LlvmpipePeer::create(error);
  if (!peer) {
    channel.send("error " + error);
    return 1;
  }
  if (!channel.send("ready " + peer->renderer())) return 1;
  bool loaded = false;
  while (const std::optional<std::string> request = channel.receive()) {
    std::string reply;
    try {
      if (request->rfind("load ", 0) == 0) {
        loaded = false;
        const PeerWorkload* workload = find_peer_workload(request->substr(5));
        if (workload == nullptr) {
          reply = "error no workload " + request->substr(5);
        } else if (!peer->load(*workload, error)) {
          reply = "error " + error;
        } else {
          loaded = true;
          const PeerCounts counts = peer->count();
          reply = "counts " + std::to_string(counts.covered) + " " + std::to_string(counts.written);
        }
      } else if (*request == "draw" && loaded) {
        const PeerDrawTime time = peer->timed_draw();
        char seconds[96];
        std::snprintf(seconds, sizeof seconds, "seconds %.9e %.9e", time.wall, time.cpu);
        reply = seconds;
      } else {
        reply = "error unexpected request: " + *request;
      }
    } catch (const std::exception& e) {
      reply = std::string("error ") + e.what();
    }
    if (!channel.send(reply)) return 1;
  }
  return 0;
}

}  // namespace edgewise::bench
