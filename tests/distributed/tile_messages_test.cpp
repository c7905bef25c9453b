// The MPI renderer's messages: what is written reads back the same, and a short or foreign
// message fails the reader instead of reading past its end.
#include "candela/distributed/tile_messages.h"

#include <gtest/gtest.h>

#include <vector>

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(TileMessages, RoundTrip) {
    MessageWriter w(TileMessageType::kResult);
    w.u32(7);
    w.i32(-15);
    w.u64(0x0123456789abcdefull);
    w.rays(RayCounters{1, 2, 3});
    const std::vector<double> values = {0.5, -1e300, 3.25, 1.0 / 3.0};
    w.doubles(values.data(), values.size());
    w.u8(9);

    MessageReader r(w.bytes());
    EXPECT_EQ(r.type(), TileMessageType::kResult);
    EXPECT_EQ(r.u32(), 7u);
    EXPECT_EQ(r.i32(), -15);
    EXPECT_EQ(r.u64(), 0x0123456789abcdefull);
    const RayCounters rays = r.rays();
    EXPECT_EQ(rays.camera, 1u);
    EXPECT_EQ(rays.bounce, 2u);
    EXPECT_EQ(rays.shadow, 3u);
    std::vector<double> back(values.size());
    ASSERT_TRUE(r.doubles(back.data(), back.size()));
    EXPECT_EQ(back, values);  // bit for bit
    EXPECT_EQ(r.u8(), 9);
    EXPECT_TRUE(r.at_end());
    EXPECT_FALSE(r.failed());
}

TEST(TileMessages, ShortMessagesFailTheReader) {
    MessageWriter w(TileMessageType::kAssign);
    w.u32(1);
    MessageReader r(w.bytes());
    EXPECT_EQ(r.type(), TileMessageType::kAssign);
    EXPECT_EQ(r.u32(), 1u);
    EXPECT_EQ(r.u64(), 0u);
    EXPECT_TRUE(r.failed());
    double d[2] = {7.0, 7.0};
    EXPECT_FALSE(r.doubles(d, 2));
    EXPECT_EQ(d[0], 7.0);  // nothing copied
}

TEST(TileMessages, UnknownTypesAreRefused) {
    const std::vector<unsigned char> empty, foreign = {0}, past = {uint8_t(TileMessageType::kEnd) + 1};
    EXPECT_FALSE(MessageReader(empty).type());
    EXPECT_FALSE(MessageReader(foreign).type());
    EXPECT_FALSE(MessageReader(past).type());
}

}  // namespace
}  // namespace candela
