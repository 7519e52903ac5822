// worker_pool.cpp — the workers' loop and the pool's start and stop (see worker_pool.h).
#include "worker_pool.h"

#include <algorithm>
#include <new>
#include <system_error>

namespace tiny3d::parallel {

worker_pool::worker_pool(int threads) : requested_(std::max(threads, 1)) {
    // A thread the system refuses (std::system_error: EAGAIN under a process limit such as
    // RLIMIT_NPROC) or memory for its bookkeeping (std::bad_alloc) ends the creation: the
    // pool runs with the workers it has, at least the caller's own thread, and says so
    // through size() < requested(). Jobs are cut by size(), so nothing is lost.
    try {
        workers_.reserve(std::size_t(requested_ - 1));
        for (int i = 1; i < requested_; ++i) workers_.emplace_back([this, i] { loop(i); });
    } catch (const std::system_error &) {
    } catch (const std::bad_alloc &) {
    }
}

worker_pool::~worker_pool() {
    stop_.store(true);
    generation_.fetch_add(1);
    notify(wake_, true);
    for (std::thread &t : workers_) t.join();
}

void worker_pool::notify(std::condition_variable &cv, bool all) {
    { std::lock_guard<std::mutex> lock(mutex_); }
    if (all) cv.notify_all();
    else cv.notify_one();
}

void worker_pool::loop(int index) {
    unsigned long long seen = 0;
    for (;;) {
        auto announced = [&] { return generation_.load() != seen; };
        if (!spin_until(announced)) {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, announced);
        }
        if (stop_.load()) return;
        seen = generation_.load();
        call_(job_, index);
        if (pending_.fetch_sub(1) == 1) notify(done_, false);
    }
}

}  // namespace tiny3d::parallel
