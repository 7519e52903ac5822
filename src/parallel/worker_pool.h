// worker_pool.h — the parallel module: a fixed set of worker threads that run one job on
// every thread and return when all are done. Used by the render context (src/raster/);
// not installed.
//
// Conventions: run(job) calls job(i) for i = 0..size()−1, i = 0 on the calling thread, and
// returns when every call has returned. Nothing is allocated per run. A job must not throw
// (the library never does). One caller at a time.
#ifndef TINY3D_WORKER_POOL_H
#define TINY3D_WORKER_POOL_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace tiny3d::parallel {

// A hint to the core that this thread is spinning (x86 PAUSE; nothing elsewhere).
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Phases of a frame follow each other within microseconds, far less than a sleep/wake-up
// through the kernel costs, so waiting threads spin first (for at most SPIN_LIMIT) and
// sleep only after.
inline constexpr std::chrono::microseconds SPIN_LIMIT{50};
inline constexpr int SPINS_PER_CLOCK_READ = 64;

// Waits until done() holds by spinning (with a pause hint) for at most SPIN_LIMIT; returns
// whether it did.
template <class Done>
bool spin_until(Done &&done) {
    const auto give_up = std::chrono::steady_clock::now() + SPIN_LIMIT;
    for (;;) {
        for (int k = 0; k < SPINS_PER_CLOCK_READ; ++k) {
            if (done()) return true;
            spin_pause();
        }
        if (std::chrono::steady_clock::now() > give_up) return false;
    }
}

// Waits until done() holds: spins with a pause hint, yielding the core every
// SPINS_PER_CLOCK_READ spins (the thread waited for may be waiting for this core).
template <class Done>
void spin_until_yielding(Done &&done) {
    for (;;) {
        for (int k = 0; k < SPINS_PER_CLOCK_READ; ++k) {
            if (done()) return;
            spin_pause();
        }
        std::this_thread::yield();
    }
}

// threads − 1 workers created once (threads ≥ 1; fewer if the system refuses threads:
// never an exception). A new job is announced by bumping
// `generation_` (the job pointer is published by that release store); workers and the
// caller spin briefly on the atomics, then sleep on the condition variables. Every state
// change is followed by locking and unlocking the mutex before notifying, so a thread that
// checked the state under the mutex just before the change is already waiting: no lost
// wake-up.
class worker_pool {
public:
    explicit worker_pool(int threads);
    ~worker_pool();
    worker_pool(const worker_pool &) = delete;
    worker_pool &operator=(const worker_pool &) = delete;
    // The threads jobs run on: requested() unless the system refused some (then fewer, ≥ 1).
    int size() const { return static_cast<int>(workers_.size()) + 1; }
    int requested() const { return requested_; }

    template <class Job>
    void run(Job &job) {
        if (workers_.empty()) {
            job(0);
            return;
        }
        call_ = [](void *j, int i) { (*static_cast<Job *>(j))(i); };
        job_ = &job;
        pending_.store(static_cast<int>(workers_.size()));
        generation_.fetch_add(1);
        notify(wake_, true);
        job(0);
        auto finished = [this] { return pending_.load() == 0; };
        if (spin_until(finished)) return;
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, finished);
    }

private:
    void notify(std::condition_variable &cv, bool all);
    void loop(int index);

    int requested_ = 1;
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    void (*call_)(void *, int) = nullptr;
    void *job_ = nullptr;
    std::atomic<unsigned long long> generation_{0};
    std::atomic<int> pending_{0};
    std::atomic<bool> stop_{false};
};

}  // namespace tiny3d::parallel

#endif
