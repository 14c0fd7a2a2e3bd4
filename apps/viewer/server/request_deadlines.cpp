#include "request_deadlines.hpp"

#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <utility>

namespace {

// The socket the listening thread accepted last. httplib 0.11 accepts a connection and hands a
// closure holding its socket to the task queue, with no hook in between and its per-connection
// function private; so the server's `accept` (which the httplib library calls) notes the socket,
// and the task queue, called next on the same thread, takes it.
thread_local int last_accepted = -1;

}  // namespace

extern "C" int accept(int fd, sockaddr* __restrict address, socklen_t* __restrict length) {
  const int sock = static_cast<int>(::syscall(SYS_accept, fd, address, length));
  last_accepted = sock;
  return sock;
}

// httplib 0.11 bounds each header line (8 KiB) but not their number: a client could send hundreds
// of megabytes of header lines within the head deadline, all kept in memory. The bytes a worker
// receives while a request head is due are counted here (httplib reads through `recv`), and a
// head over its limit ends the connection.
extern "C" ssize_t recv(int fd, void* buffer, size_t length, int flags) {
  const auto got =
      static_cast<ssize_t>(::syscall(SYS_recvfrom, fd, buffer, length, flags, nullptr, nullptr));
  if (got > 0 &&
      !pgamesh::viewer::RequestWatchdog::head_bytes_received(static_cast<std::size_t>(got))) {
    ::shutdown(fd, SHUT_RDWR);
    return 0;  // as if the client had closed: httplib ends the connection
  }
  return got;
}

namespace pgamesh::viewer {

namespace {

// The connection of this worker thread: httplib serves a connection on one worker from accept to
// close, and calls the pre-routing handler and the logger on that thread.
struct Current {
  RequestWatchdog* watchdog = nullptr;
  void* connection = nullptr;
};
thread_local Current current;

// How often the watchdog looks: deadlines hold to within this.
constexpr std::chrono::milliseconds kWatchInterval{100};

}  // namespace

class RequestWatchdog::WatchedQueue : public httplib::TaskQueue {
 public:
  WatchedQueue(RequestWatchdog& watchdog, std::size_t threads)
      : watchdog_(watchdog), pool_(threads) {}

  void enqueue(std::function<void()> fn) override {
    Connection* c = watchdog_.add(std::exchange(last_accepted, -1));
    pool_.enqueue([this, c, fn = std::move(fn)] {
      watchdog_.start(c);
      current = {&watchdog_, c};
      fn();
      current = {};
      watchdog_.remove(c);
    });
  }
  void shutdown() override { pool_.shutdown(); }

 private:
  RequestWatchdog& watchdog_;
  httplib::ThreadPool pool_;
};

RequestWatchdog::RequestWatchdog(RequestDeadlines deadlines)
    : deadlines_(deadlines), thread_([this] { watch(); }) {}

RequestWatchdog::~RequestWatchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

httplib::TaskQueue* RequestWatchdog::new_task_queue(std::size_t threads) {
  return new WatchedQueue(*this, threads);
}

RequestWatchdog::Connection* RequestWatchdog::add(int sock) {
  // The duplicate keeps the socket's number from going to a later connection while the watchdog
  // may still shut it down; shutdown() acts on the socket, whichever descriptor names it.
  const int watched = sock >= 0 ? ::dup(sock) : -1;
  std::lock_guard<std::mutex> lock(mutex_);
  Connection& c = connections_.emplace_back();
  c.watched_fd = watched;
  return &c;
}

void RequestWatchdog::start(Connection* c) {
  std::lock_guard<std::mutex> lock(mutex_);
  c->started = true;
  c->since = std::chrono::steady_clock::now();
}

void RequestWatchdog::remove(Connection* c) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (c->watched_fd >= 0) ::close(c->watched_fd);
  connections_.remove_if([c](const Connection& x) { return &x == c; });
}

void RequestWatchdog::phase(bool in_head) {
  auto* c = static_cast<Connection*>(current.connection);
  std::lock_guard<std::mutex> lock(mutex_);
  c->in_head = in_head;
  c->head_bytes = 0;
  c->since = std::chrono::steady_clock::now();
}

bool RequestWatchdog::head_bytes_received(std::size_t bytes) {
  if (!current.watchdog) return true;
  auto* c = static_cast<Connection*>(current.connection);
  if (!c->in_head) return true;  // only this thread changes it
  c->head_bytes += bytes;
  return c->head_bytes <= current.watchdog->deadlines_.head_bytes;
}

void RequestWatchdog::head_received() {
  if (current.watchdog) current.watchdog->phase(false);
}

void RequestWatchdog::answer_sent() {
  if (current.watchdog) current.watchdog->phase(true);
}

void RequestWatchdog::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, kWatchInterval);
    const auto now = std::chrono::steady_clock::now();
    for (Connection& c : connections_) {
      if (!c.started || c.cut || c.watched_fd < 0) continue;
      if (now - c.since > (c.in_head ? deadlines_.head : deadlines_.request)) {
        ::shutdown(c.watched_fd, SHUT_RDWR);
        c.cut = true;
      }
    }
  }
}

}  // namespace pgamesh::viewer
