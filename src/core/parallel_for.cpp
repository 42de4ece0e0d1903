// A small fork-join loop on std::thread, for pure per-item work.
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "cic/core/parallel_for.hpp"

namespace cic {

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
    if (threads <= 1 || n <= 1) {
        for (std::size_t i = 0; i < n; ++i) fn(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex m;
    std::size_t error_index = n;
    std::exception_ptr error;
    auto work = [&] {
        for (;;) {
            const std::size_t i = next.fetch_add(1);
            if (i >= n || stop.load()) return;
            try {
                fn(i);
            } catch (...) {
                std::lock_guard lock(m);
                if (i < error_index) {
                    error_index = i;
                    error = std::current_exception();
                }
                stop = true;
            }
        }
    };
    const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(threads), n);
    std::vector<std::thread> pool;
    pool.reserve(count - 1);
    for (std::size_t t = 1; t < count; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

int hardware_threads() {
    const unsigned h = std::thread::hardware_concurrency();
    return h == 0 ? 1 : static_cast<int>(h);
}

} // namespace cic
