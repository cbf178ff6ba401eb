// A worker thread that builds the newest request only. A drag asks for dozens of models
// a second and only the last one matters: a request made while another is being built
// replaces any that still waits, and the results wait for the UI thread to take them.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace pw::edit {

// Lowers the calling thread's priority below the UI thread's (nice 5; Linux gives each
// thread its own): a model worker's, so that on two cores the frames come first.
void lowerThreadPriority();

template <class Request, class Done>
class LatestWorker {
 public:
  // Hands a result to the UI thread (a build may hand over more than one).
  using Emit = std::function<void(Done)>;
  // Whether a newer request waits (or the worker is stopping): a build may stop early.
  using Superseded = std::function<bool()>;
  using Build = std::function<void(Request&, const Emit&, const Superseded&)>;

  // `build` runs on the worker thread (at a lowered priority), one request at a time.
  explicit LatestWorker(Build build) : build_(std::move(build)), thread_([this] { run(); }) {}
  ~LatestWorker() {  // waits for the build in progress, then stops
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  LatestWorker(const LatestWorker&) = delete;
  LatestWorker& operator=(const LatestWorker&) = delete;

  void request(Request request) {
    {
      std::lock_guard lock(mutex_);
      pending_ = std::move(request);
    }
    wake_.notify_one();
  }
  // What finished since the last call, oldest first. Never waits for a build.
  std::vector<Done> takeDone() {
    std::lock_guard lock(mutex_);
    std::vector<Done> done = std::move(done_);
    done_.clear();
    return done;
  }
  // A request waits or is being built.
  bool busy() const {
    std::lock_guard lock(mutex_);
    return building_ || pending_.has_value();
  }
  // A result waits to be taken.
  bool hasDone() const {
    std::lock_guard lock(mutex_);
    return !done_.empty();
  }

 private:
  void run() {
    lowerThreadPriority();
    const Emit emit = [this](Done done) {
      std::lock_guard lock(mutex_);
      done_.push_back(std::move(done));
    };
    const Superseded superseded = [this] {
      std::lock_guard lock(mutex_);
      return pending_.has_value() || stop_;
    };
    for (;;) {
      Request request;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || pending_.has_value(); });
        if (stop_) return;
        request = std::move(*pending_);
        pending_.reset();
        building_ = true;
      }
      build_(request, emit, superseded);
      std::lock_guard lock(mutex_);
      building_ = false;
    }
  }

  const Build build_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Request> pending_;
  std::vector<Done> done_;
  bool building_ = false;
  bool stop_ = false;
  std::thread thread_;  // last: started once the rest exists
};

}  // namespace pw::edit
