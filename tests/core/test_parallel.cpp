// parallel_for (ek/core/parallel.hpp): every index once, the first failure rethrown.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "ek/core/parallel.hpp"

using namespace ek;

TEST(ParallelFor, EveryIndexExactlyOnceOnSeveralThreads) {
  for (int jobs : {1, 2, 4}) {
    std::vector<std::atomic<int>> hits(1000);
    std::mutex m;
    std::vector<std::thread::id> threads;
    parallel_for(hits.size(), jobs, [&](size_t i) {
      ++hits[i];
      std::lock_guard<std::mutex> lock(m);
      if (std::find(threads.begin(), threads.end(), std::this_thread::get_id()) == threads.end())
        threads.push_back(std::this_thread::get_id());
    });
    for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
    EXPECT_LE(threads.size(), static_cast<size_t>(jobs));
  }
}

TEST(ParallelFor, SerialRunsInOrderOnTheCallingThread) {
  std::vector<size_t> order;
  const auto caller = std::this_thread::get_id();
  parallel_for(5, 1, [&](size_t i) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
  parallel_for(0, 4, [&](size_t) { ADD_FAILURE() << "no index for an empty range"; });
}

TEST(ParallelFor, TheFailureOfTheSmallestIndexIsRethrownAfterAllThreadsEnd) {
  for (int jobs : {1, 3}) {
    std::atomic<int> running{0};
    try {
      parallel_for(100, jobs, [&](size_t i) {
        ++running;
        if (i == 7 || i == 9) throw std::runtime_error("item " + std::to_string(i));
        --running;
      });
      ADD_FAILURE() << "expected an exception";
    } catch (const std::runtime_error& e) {
      // every thread has finished: only failed items are still counted as
      // running; index 7 is handed out before 9, so it always ran and failed
      EXPECT_GE(running.load(), 1);
      EXPECT_LE(running.load(), 2);
      EXPECT_STREQ(e.what(), "item 7");
    }
  }
}
