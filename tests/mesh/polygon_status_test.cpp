// The sweep status (polygon_status.hpp, internal): a treap of items in their order, against
// std::set over random runs of insertions (by search, and just below a neighbour, right or
// wrong), removals (which return the item just above) and walks up and down; nodes freed
// by removals are used again, and handles of items still there stay valid.

#include "../../mesh/src/polygon_status.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using Status = SweepStatus<int, std::less<int>>;

/// The status's items from the bottom up (by previous() from the top), and from the top
/// down (by next() from the bottom), which must agree.
std::vector<int> items(const Status& status) {
  std::vector<int> down;
  Status::Handle h = status.last();
  Status::Handle bottom = Status::kNone;
  for (; h != Status::kNone; h = status.previous(h)) {
    down.push_back(status[h]);
    bottom = h;
  }
  std::vector<int> up;
  for (h = bottom; h != Status::kNone; h = status.next(h))
    up.push_back(status[h]);
  EXPECT_EQ(std::vector<int>(down.rbegin(), down.rend()), up);
  return up;
}

TEST(SweepStatus, AgreesWithASetOverRandomRuns) {
  auto rng = testing::seeded_engine("mesh.polygon_status");
  std::uniform_int_distribution<int> value(0, 400);
  std::uniform_int_distribution<int> action(0, 9);
  for (int run = 0; run < 20; ++run) {
    Status status{std::less<int>()};
    std::set<int> truth;
    std::map<int, Status::Handle> handle;
    for (int step = 0; step < 2000; ++step) {
      const int a = action(rng);
      if (a < 4 || truth.empty()) {  // insert a new item, by search or below a neighbour
        int x = value(rng);
        while (truth.count(x) != 0)
          x = value(rng);
        const auto above = truth.upper_bound(x);
        const Status::Handle right = above == truth.end() ? Status::kNone : handle[*above];
        Status::Handle h;
        if (a == 0 || truth.empty()) {
          h = status.insert(x);
        } else if (a == 1) {
          h = status.insert_below(x, right);
        } else if (a == 2) {
          h = status.try_insert_below(x, right);
        } else {
          // A wrong neighbour (the top when something is above x, else the lowest item):
          // refused by try_insert_below, searched past by insert_below.
          const Status::Handle wrong =
              right != Status::kNone ? Status::kNone : handle[*truth.begin()];
          EXPECT_EQ(status.try_insert_below(x, wrong), Status::kNone);
          h = status.insert_below(x, wrong);
        }
        ASSERT_NE(h, Status::kNone);
        ASSERT_EQ(status[h], x);
        truth.insert(x);
        handle[x] = h;
      } else if (a < 8) {  // remove an item
        auto it = truth.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, truth.size() - 1)(rng));
        const int x = *it;
        const auto above = std::next(it);
        const Status::Handle up = status.erase(handle[x]);
        if (above == truth.end()) {
          EXPECT_EQ(up, Status::kNone);
        } else {
          ASSERT_NE(up, Status::kNone);
          EXPECT_EQ(status[up], *above);
        }
        truth.erase(it);
        handle.erase(x);
      } else {  // neighbours of a random item
        auto it = truth.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, truth.size() - 1)(rng));
        const Status::Handle h = handle[*it];
        const Status::Handle below = status.previous(h), above = status.next(h);
        ASSERT_EQ(below == Status::kNone, it == truth.begin());
        if (below != Status::kNone) {
          EXPECT_EQ(status[below], *std::prev(it));
        }
        ASSERT_EQ(above == Status::kNone, std::next(it) == truth.end());
        if (above != Status::kNone) {
          EXPECT_EQ(status[above], *std::next(it));
        }
      }
      if (step % 50 == 0) {
        ASSERT_EQ(items(status), std::vector<int>(truth.begin(), truth.end()))
            << "run " << run << ", step " << step;
      }
    }
    ASSERT_EQ(items(status), std::vector<int>(truth.begin(), truth.end()));
    EXPECT_EQ(status.empty(), truth.empty());
  }
}

TEST(SweepStatus, AnEmptyStatusAndOneItem) {
  Status status{std::less<int>()};
  EXPECT_TRUE(status.empty());
  EXPECT_EQ(status.last(), Status::kNone);
  const Status::Handle five = status.try_insert_below(5, Status::kNone);  // at the top
  ASSERT_NE(five, Status::kNone);
  EXPECT_EQ(status.last(), five);
  EXPECT_EQ(status[five], 5);
  EXPECT_EQ(status.previous(five), Status::kNone);
  EXPECT_EQ(status.next(five), Status::kNone);
  EXPECT_EQ(status.try_insert_below(7, five), Status::kNone);  // 7 is not below 5
  EXPECT_EQ(status.erase(five), Status::kNone);
  EXPECT_TRUE(status.empty());
}

}  // namespace
}  // namespace exactgeo::mesh::internal
