// Whole-request deadlines for cpp-httplib 0.11, which bounds each read and write (a byte every few
// seconds keeps a connection alive) but not a request: a client that trickles its request head or
// body would hold one of the server's workers for as long as it likes (slowloris). A watchdog shuts
// down the socket of a connection that overruns (docs/viewer.md, "Limits"):
//
//  * the head: from the moment a worker takes the connection, or from the end of the previous
//    answer on a kept-alive connection, the request line and headers must be in within `head`;
//  * the rest: from the end of the head, the body must be read and the answer written within
//    `request`;
//  * and a head may not exceed `head_bytes` (httplib bounds each header line, not their number).
//
// Shutting the socket down (not closing it) makes httplib's blocked read or write fail; httplib
// then ends the connection and closes the socket itself.
#pragma once

#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <list>
#include <mutex>
#include <thread>

namespace pgamesh::viewer {

struct RequestDeadlines {
  std::chrono::milliseconds head{10000};
  std::chrono::milliseconds request{60000};
  // Bytes a worker may receive while a request head is due: the line and headers, and what
  // httplib's 4 KiB line buffer reads beyond them. A head over it ends the connection.
  std::size_t head_bytes = std::size_t{64} << 10;
};

class RequestWatchdog {
 public:
  explicit RequestWatchdog(RequestDeadlines deadlines);
  ~RequestWatchdog();
  RequestWatchdog(const RequestWatchdog&) = delete;
  RequestWatchdog& operator=(const RequestWatchdog&) = delete;

  // httplib's task queue with each connection watched: `threads` workers, as httplib::ThreadPool.
  httplib::TaskQueue* new_task_queue(std::size_t threads);

  // Called on the connection's worker thread: from the pre-routing handler (the head is in) and
  // from the logger (the answer is out).
  static void head_received();
  static void answer_sent();
  // Counts bytes received on this worker's connection while its request head is due; false when
  // they exceed RequestDeadlines::head_bytes (the connection is then ended).
  static bool head_bytes_received(std::size_t bytes);

 private:
  struct Connection {
    int watched_fd = -1;  // a duplicate of the socket, open until the connection's entry goes
    bool started = false;
    bool in_head = true;
    bool cut = false;
    std::size_t head_bytes = 0;  // received since the head became due; this worker's own count
    std::chrono::steady_clock::time_point since;
  };
  class WatchedQueue;

  Connection* add(int sock);
  void start(Connection* c);
  void remove(Connection* c);
  void phase(bool in_head);
  void watch();

  RequestDeadlines deadlines_;
  std::mutex mutex_;
  std::list<Connection> connections_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace pgamesh::viewer
