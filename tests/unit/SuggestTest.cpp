// "Did you mean": the edit distance and when a guess is close enough to offer.
#include "core/Suggest.h"

#include <gtest/gtest.h>

namespace pb {
namespace {

TEST(Suggest, EditDistanceCountsInsertDeleteSubstitute) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("abc", ""), 3u);
    EXPECT_EQ(editDistance("quik", "quick"), 1u);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("ROOMS", "rooms"), 0u); // case-insensitive
}

TEST(Suggest, OffersTheClosestLikelyTypo) {
    const std::vector<std::string> scenes{"cornell", "rooms", "courtyard", "empty"};
    EXPECT_EQ(closestName("rooom", scenes), "rooms");
    EXPECT_EQ(closestName("cornel", scenes), "cornell");
    EXPECT_EQ(closestName("courtyrad", scenes), "courtyard");
    EXPECT_EQ(didYouMean("rooom", scenes), "; did you mean 'rooms'?");
}

TEST(Suggest, OffersNothingForAWildGuess) {
    const std::vector<std::string> scenes{"cornell", "rooms", "courtyard", "empty"};
    EXPECT_EQ(closestName("sponza", scenes), "");
    EXPECT_EQ(didYouMean("xyz", scenes), "");
    EXPECT_EQ(closestName("anything", {}), "");
}

} // namespace
} // namespace pb
