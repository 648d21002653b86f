// SharedPrepare: a value made once per key however many threads ask, exceptions handed to every
// asker, keys that tell bit patterns apart.
#include "framework/model/shared_prepare.h"

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

TEST(SharedPrepare, MakesEachKeyOnce) {
  SharedPrepare shared;
  std::atomic<int> made{0};
  auto make = [&made] {
    ++made;
    return std::vector<double>{1.0, 2.0};
  };
  std::vector<std::shared_ptr<const std::vector<double>>> got(8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) {
    threads.emplace_back(
        [&, t] { got[t] = shared.Get<std::vector<double>>("a", std::function(make)); });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(made.load(), 1);
  for (const auto& v : got) EXPECT_EQ(v.get(), got[0].get());  // one object, read by all
  EXPECT_EQ((*got[0])[1], 2.0);
  shared.Get<std::vector<double>>("b", std::function(make));
  EXPECT_EQ(made.load(), 2);
  EXPECT_EQ(shared.size(), 2);
}

TEST(SharedPrepare, TypesDoNotShareAKey) {
  SharedPrepare shared;
  EXPECT_EQ(*shared.Get<int>("k", std::function([] { return 3; })), 3);
  EXPECT_EQ(*shared.Get<double>("k", std::function([] { return 0.5; })), 0.5);
}

TEST(SharedPrepare, EveryAskerGetsTheMakersException) {
  SharedPrepare shared;
  int made = 0;
  auto fail = [&made]() -> int {
    ++made;
    throw std::runtime_error("no elements");
  };
  EXPECT_THROW(shared.Get<int>("k", std::function(fail)), std::runtime_error);
  EXPECT_THROW(shared.Get<int>("k", std::function(fail)), std::runtime_error);
  EXPECT_EQ(made, 1);
}

TEST(SharedPrepare, KeysTellBitPatternsApart) {
  std::string a, b, c;
  AppendKey(&a, 0.1);
  AppendKey(&b, std::nextafter(0.1, 1.0));
  AppendKey(&c, 0.1);
  EXPECT_NE(a, b);
  EXPECT_EQ(a, c);
  std::string zero, negative_zero;
  AppendKey(&zero, 0.0);
  AppendKey(&negative_zero, -0.0);
  EXPECT_NE(zero, negative_zero);
}

}  // namespace
}  // namespace fitfeel
