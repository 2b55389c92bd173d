// Contact identity (contact/contact_identity.hpp) for both kinds of friction memory: the
// same rules (key by pair and feature, nearest record of the pair within the radius, a fresh
// slot above every slot handed out) whatever the record holds, checked against the rules
// written out directly on random record lists.
#include "contact/contact_identity.hpp"

#include <gtest/gtest.h>

#include <random>

#include "contact/dynamic_friction.hpp"
#include "contact/stick_anchor.hpp"
#include "support/contact_point_at.hpp"

namespace tribo::contact {
namespace {

using Eigen::Vector3d;

ContactPoint point(int pair, int feature, const Vector3d& p) {
  return test::contactPointAt(pair, feature, p);
}

template <class Record>
Record record(std::uint64_t key, const Vector3d& p) {
  Record r;
  r.key = key;
  r.position = p;
  return r;
}

template <class Record>
class ContactIdentity : public ::testing::Test {};
using RecordKinds = ::testing::Types<StickAnchor, FrictionStateRecord>;
TYPED_TEST_SUITE(ContactIdentity, RecordKinds);

TYPED_TEST(ContactIdentity, FeaturePointsKeepTheirKeyAndOthersMatchTheNearestOfTheirPair) {
  using R = TypeParam;
  const std::vector<R> records{record<R>(contactKey(0, 3), {0, 0, 0}),
                               record<R>(contactKey(1, kFreshSlot), {1, 0, 0}),
                               record<R>(contactKey(1, kFreshSlot + 1), {1.5, 0, 0}),
                               record<R>(contactKey(2, 0), {1.0, 0, 0})};
  const std::span<const R> list(records);
  EXPECT_EQ(findRecord(list, point(0, 3, {9, 9, 9}), 0.01), &records[0]);  // by feature
  EXPECT_EQ(findRecord(list, point(0, 2, {0, 0, 0}), 0.01), nullptr);      // other feature
  EXPECT_EQ(findRecord(list, point(1, -1, {1.004, 0, 0}), 0.01), &records[1]);
  EXPECT_EQ(findRecord(list, point(1, -1, {1.496, 0, 0}), 0.01), &records[2]);
  EXPECT_EQ(findRecord(list, point(1, -1, {1.2, 0, 0}), 0.01), nullptr);  // too far
  // A feature record of pair 2 at the same place is not a feature-less point's match.
  EXPECT_EQ(findRecord(list, point(2, -1, {1.0, 0, 0}), 0.01), nullptr);
  EXPECT_EQ(findRecord(std::span<const R>(), point(1, -1, {1, 0, 0}), 0.01), nullptr);
}

// The first fresh slot as the rule says it: above every slot >= kFreshSlot of the pair.
template <class R>
std::uint64_t freshSlotByDefinition(const std::vector<R>& records, int pair) {
  std::uint64_t slot = kFreshSlot;
  for (const R& r : records)
    if (keyPair(r.key) == pair && keySlot(r.key) >= kFreshSlot)
      slot = std::max(slot, keySlot(r.key) + 1);
  return slot;
}

TYPED_TEST(ContactIdentity, FreshSlotsAreAboveEverySlotOfThePairOnRandomLists) {
  using R = TypeParam;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pair_of(0, 5), feature(0, 40), fresh(0, 12), kind(0, 2);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<R> records;
    const int n = trial % 30;
    for (int i = 0; i < n; ++i) {
      const std::uint64_t slot = kind(rng) == 0
                                     ? static_cast<std::uint64_t>(feature(rng))
                                     : kFreshSlot + static_cast<std::uint64_t>(fresh(rng));
      records.push_back(record<R>(contactKey(pair_of(rng), slot), Vector3d::Zero()));
    }
    std::sort(records.begin(), records.end(), [](const R& a, const R& b) { return a.key < b.key; });
    for (int pair = 0; pair <= 6; ++pair)
      ASSERT_EQ(freshSlotAbove(std::span<const R>(records), pair),
                freshSlotByDefinition(records, pair))
          << "trial " << trial << ", pair " << pair;
  }
}

TYPED_TEST(ContactIdentity, TheFirstClaimantKeepsARecordAndTheNextGetsASlotAboveAllHandedOut) {
  using R = TypeParam;
  std::vector<R> records{record<R>(contactKey(1, kFreshSlot), {1, 0, 0}),
                         record<R>(contactKey(1, kFreshSlot + 4), {2, 0, 0}),
                         record<R>(contactKey(3, 2), {0, 0, 0})};
  RecordBook<R> book;
  book.begin(records);
  const ContactPoint p = point(1, -1, {1, 0, 0});
  EXPECT_EQ(book.claim(p, &records[0]), records[0].key);
  EXPECT_EQ(book.claim(p, &records[0]), contactKey(1, kFreshSlot + 5));  // above the old +4
  EXPECT_EQ(book.claim(p, nullptr), contactKey(1, kFreshSlot + 6));      // above the new +5
  EXPECT_EQ(book.claim(point(2, -1, {0, 0, 0}), nullptr), contactKey(2, kFreshSlot));
  EXPECT_EQ(book.claim(point(3, 2, {5, 5, 5}), nullptr), contactKey(3, 2));  // by feature

  // finish(): unchanged lists stay put; changed ones come back sorted by key.
  book.begin(records);
  for (const R& r : records) book.add(r);
  const std::vector<R> before = records;
  EXPECT_FALSE(book.finish(records));
  EXPECT_EQ(records, before);
  book.begin(records);
  book.add(record<R>(contactKey(2, 1), {0, 0, 0}));
  book.add(record<R>(contactKey(0, 9), {0, 0, 0}));
  EXPECT_TRUE(book.finish(records));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].key, contactKey(0, 9));
  EXPECT_EQ(records[1].key, contactKey(2, 1));
}

}  // namespace
}  // namespace tribo::contact
