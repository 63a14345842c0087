#include "clip/bounded_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <numeric>
#include <thread>
#include <vector>

namespace bookspin::clip {
namespace {

TEST(BoundedQueue, IsFifoAndDrainsAfterClose) {
  BoundedQueue<int> queue(3);
  EXPECT_TRUE(queue.push(1));
  EXPECT_TRUE(queue.push(2));
  queue.close();
  EXPECT_FALSE(queue.push(3));
  EXPECT_EQ(queue.pop(), 1);
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_EQ(queue.pop(), std::nullopt);
  EXPECT_THROW(BoundedQueue<int>(0), std::invalid_argument);
}

TEST(BoundedQueue, ProducerBlocksAtCapacityUntilAConsumerPops) {
  BoundedQueue<int> queue(2);
  std::atomic<int> pushed{0};
  std::thread producer([&] {
    for (int i = 0; i < 3; ++i) {
      queue.push(i);
      ++pushed;
    }
  });
  // The first two pushes land however loaded the machine is (up to 30 s); then, 50 ms on,
  // the third still waits for room. A queue that did not block would have taken it at once.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (pushed.load() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(pushed.load(), 2);  // (no ASSERT: the pop below lets the producer finish)
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(pushed.load(), 2);  // third push waits for room
  EXPECT_EQ(queue.size(), 2u);
  EXPECT_EQ(queue.pop(), 0);
  producer.join();
  EXPECT_EQ(pushed.load(), 3);
}

TEST(BoundedQueue, CloseWakesABlockedConsumer) {
  BoundedQueue<int> queue(1);
  std::thread consumer([&] { EXPECT_EQ(queue.pop(), std::nullopt); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  queue.close();
  consumer.join();
}

// pop_for gives up after its timeout on an empty queue, takes an item that is there, and tells
// "none yet" from "closed and drained" by closed().
TEST(BoundedQueue, PopForReturnsNothingAfterItsTimeoutAndDrainsAfterClose) {
  BoundedQueue<int> queue(1);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(queue.pop_for(std::chrono::milliseconds(20)), std::nullopt);
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(20));
  EXPECT_FALSE(queue.closed());
  std::thread producer([&] {
    queue.push(7);
    queue.close();
  });
  std::optional<int> item;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!item && std::chrono::steady_clock::now() < deadline)
    item = queue.pop_for(std::chrono::milliseconds(10));
  producer.join();
  EXPECT_EQ(item, 7);
  EXPECT_EQ(queue.pop_for(std::chrono::milliseconds(10)), std::nullopt);
  EXPECT_TRUE(queue.closed());
}

TEST(BoundedQueue, ManyProducersAndConsumersLoseNothing) {
  BoundedQueue<int> queue(4);
  constexpr int kProducers = 3, kPerProducer = 1000;
  std::atomic<long> sum{0};
  std::vector<std::thread> consumers, producers;
  for (int c = 0; c < 2; ++c) {
    consumers.emplace_back([&] {
      while (auto item = queue.pop()) sum += *item;
    });
  }
  for (int p = 0; p < kProducers; ++p) {
    producers.emplace_back([&, p] {
      for (int i = 0; i < kPerProducer; ++i) queue.push(p * kPerProducer + i);
    });
  }
  for (auto& t : producers) t.join();
  queue.close();
  for (auto& t : consumers) t.join();
  const long n = kProducers * kPerProducer;
  EXPECT_EQ(sum.load(), n * (n - 1) / 2);
}

}  // namespace
}  // namespace bookspin::clip
