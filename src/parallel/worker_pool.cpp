// worker_pool.cpp — the workers' loop and the pool's start and stop (see worker_pool.h).
#include "worker_pool.h"

namespace tiny3d::parallel {

worker_pool::worker_pool(int threads) {
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { loop(i); });
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
