// Checkpoint files: an exact round trip, a clear refusal of anything that is not a checkpoint of
// this render, and never a crash on a damaged file.
#include "candela/render/job/checkpoint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "candela/core/error.h"
#include "candela/core/hash64.h"
#include "support/render_identity.h"
#include "support/scene_error_of.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
    fs::path dir = fs::path(CANDELA_TEST_BINARY_DIR) / "checkpoint";
    fs::create_directories(dir);
    fs::remove(dir / name);
    return dir / name;
}

using test::read_bytes;

void write_bytes(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

RenderIdentity identity() { return test::render_identity_of_size(5, 3); }

// Sums that need all 64 bits to round-trip: thirds, a denormal, a negative zero, huge values.
RenderState state() {
    std::vector<PixelSum> sums(15);
    for (size_t i = 0; i < sums.size(); ++i)
        sums[i] = {double(i) / 3.0, std::ldexp(1.0 + double(i), -1060), -double(i) * 1e300};
    sums[0][0] = -0.0;
    return RenderState{Film(5, 3, std::move(sums)), 17, 4};
}

// The header's size for identity(): magic, format version, three names, hash, seed, width,
// height, samples done, dropped samples.
constexpr size_t kHeaderBytes = 8 + 4 + (4 + 5) + (4 + 4) + (4 + 11) + 8 + 8 + 4 + 4 + 4 + 8;

using test::error_of;

TEST(Checkpoint, RoundTripIsExact) {
    const fs::path file = temp_file("round_trip.ckpt");
    const RenderState written = state();
    write_checkpoint(file, identity(), written);
    const Checkpoint c = read_checkpoint(file);
    const RenderIdentity id = identity();
    EXPECT_EQ(c.identity.candela_version, id.candela_version);
    EXPECT_EQ(c.identity.integrator, id.integrator);
    EXPECT_EQ(c.identity.sampler, id.sampler);
    EXPECT_EQ(c.identity.content_hash, id.content_hash);
    EXPECT_EQ(c.identity.seed, id.seed);
    EXPECT_EQ(c.identity.width, 5);
    EXPECT_EQ(c.identity.height, 3);
    EXPECT_EQ(c.state.samples_done, 17u);
    EXPECT_EQ(c.state.dropped_samples, 4u);
    ASSERT_EQ(c.state.film.width(), 5);
    ASSERT_EQ(c.state.film.height(), 3);
    ASSERT_EQ(c.state.film.sums().size(), written.film.sums().size());
    EXPECT_EQ(std::memcmp(c.state.film.sums().data(), written.film.sums().data(),
                          written.film.sums().size() * sizeof(PixelSum)),
              0);
    EXPECT_TRUE(std::signbit(c.state.film.sum(0, 0)[0]));
    // The header, the sums, the checksum.
    EXPECT_EQ(fs::file_size(file), kHeaderBytes + 15 * 24 + 8);
}

TEST(Checkpoint, LargeFilmRoundTripIsExact) {
    // More than one 64 KiB block of sums, behind a header whose length is not a multiple of 8: the
    // checksum is computed in pieces when writing and in one go when reading.
    const int w = 100, h = 50;
    std::vector<PixelSum> sums(size_t(w * h));
    for (size_t i = 0; i < sums.size(); ++i) sums[i] = {double(i) / 7.0, double(i) * 1e-3, -double(i)};
    RenderIdentity id = identity();
    id.width = w;
    id.height = h;
    const fs::path file = temp_file("large.ckpt");
    write_checkpoint(file, id, RenderState{Film(w, h, sums), 3, 0});
    const Checkpoint c = read_checkpoint(file);
    EXPECT_EQ(std::memcmp(c.state.film.sums().data(), sums.data(), sums.size() * sizeof(PixelSum)), 0);
}

// A film with AOV sums (format version 4), weighted or not: every value comes back, through
// Film::read_region's order, and the header's layers say which sums there are.
TEST(Checkpoint, AovFilmRoundTripIsExact) {
    for (bool weighted : {false, true}) {
        AovLayers aovs;
        aovs.add(AovLayer::kNormal);
        aovs.add(AovLayer::kDepth);
        Film film(5, 3, weighted, aovs);
        const PixelBounds all{0, 0, 5, 3};
        std::vector<double> values(size_t(15 * film.values_per_pixel()));
        ASSERT_EQ(film.values_per_pixel(), (weighted ? 4 : 3) + 4);
        for (size_t i = 0; i < values.size(); ++i) values[i] = double(i) / 3.0 - 7.0;
        film.write_region(all, values.data());
        const fs::path file = temp_file("aovs.ckpt");
        write_checkpoint(file, identity(), RenderState{film, 17, 4});
        const Checkpoint c = read_checkpoint(file);
        EXPECT_EQ(c.identity.aov_layers, aovs.mask());
        EXPECT_EQ(c.state.film.weighted(), weighted);
        EXPECT_TRUE(c.state.film.aovs() == aovs);
        std::vector<double> back(values.size());
        c.state.film.read_region(all, back.data());
        EXPECT_EQ(std::memcmp(back.data(), values.data(), values.size() * sizeof(double)), 0);
        // The header with the film-values word and the (empty) adaptive settings, the values, the
        // checksum.
        EXPECT_EQ(fs::file_size(file), kHeaderBytes + 12 + values.size() * 8 + 8);
        EXPECT_EQ(read_bytes(file)[8], 4);

        // The layers are part of what must match to resume, with their names in the message.
        RenderIdentity none = identity();
        const std::string message = error_of([&] { check_checkpoint_matches(file, c.identity, none); });
        EXPECT_NE(message.find("cannot resume: the checkpoint has the AOV layers normal, depth, this render none "
                               "(give the same --aov)"),
                  std::string::npos)
            << message;
    }
}

TEST(Checkpoint, FilmsWithoutAovsKeepTheirFormats) {
    const fs::path file = temp_file("plain.ckpt");
    write_checkpoint(file, identity(), state());
    const std::string bytes = read_bytes(file);
    EXPECT_EQ(bytes[8], 1);  // format version 1, as before AOVs
    write_checkpoint(file, identity(), RenderState{Film(5, 3, true), 1, 0});
    EXPECT_EQ(read_bytes(file)[8], 2);
}

TEST(Checkpoint, CorruptAovHeaderIsRefused) {
    AovLayers aovs;
    aovs.add(AovLayer::kAlbedo);
    const fs::path file = temp_file("aov_header.ckpt");
    write_checkpoint(file, identity(), RenderState{Film(5, 3, false, aovs), 1, 0});
    std::string bytes = read_bytes(file);
    bytes[kHeaderBytes + 1] = char(0x40);  // bit 14 of the film-values word: a layer past the last
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("corrupt checkpoint header: film values 0x4000"),
              std::string::npos);
    write_checkpoint(file, identity(), RenderState{Film(5, 3, false, aovs), 1, 0});
    bytes = read_bytes(file);
    bytes[kHeaderBytes + 4] = 16;  // adaptive sampling's min_spp, without statistics or a threshold
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("adaptive sampling settings 16, 0x0"), std::string::npos);
}

// The checksum's hash (core/hash64.h): the same value however the bytes arrive.
TEST(Hash64, SameValueHoweverTheBytesAreSplit) {
    std::string bytes(61, '\0');
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 37 + 11);
    Hash64 whole;
    whole.add(bytes.data(), bytes.size());
    for (size_t a = 0; a <= bytes.size(); ++a) {
        for (size_t b = a; b <= bytes.size(); b += 3) {
            Hash64 parts;
            parts.add(bytes.data(), a);
            parts.add(bytes.data() + a, b - a);
            parts.add(bytes.data() + b, bytes.size() - b);
            ASSERT_EQ(parts.value(), whole.value()) << a << ", " << b;
        }
    }
    // And it tells apart inputs that differ in one bit or in trailing zero bytes.
    Hash64 flipped, longer;
    bytes[30] = char(bytes[30] ^ 1);
    flipped.add(bytes.data(), bytes.size());
    bytes[30] = char(bytes[30] ^ 1);
    longer.add(bytes.data(), bytes.size());
    longer.add(std::string_view("\0", 1));
    EXPECT_NE(flipped.value(), whole.value());
    EXPECT_NE(longer.value(), whole.value());
}

TEST(Checkpoint, MatchingIdentityIsAccepted) {
    EXPECT_NO_THROW(check_checkpoint_matches("x.ckpt", identity(), identity()));
}

TEST(Checkpoint, EachDifferenceIsRefusedByName) {
    struct Case {
        std::function<void(RenderIdentity&)> change;
        const char* expected;
    };
    const Case cases[] = {
        {[](RenderIdentity& id) { id.candela_version = "0.0.9"; }, "written by candela 0.0.9, this is candela 0.1.0"},
        {[](RenderIdentity& id) { id.width = 6; }, "the checkpoint is 6x3, this render 5x3"},
        {[](RenderIdentity& id) { id.height = 4; }, "the checkpoint is 5x4, this render 5x3"},
        {[](RenderIdentity& id) { id.seed = 7; }, "the checkpoint has seed 7, this render seed 42"},
        {[](RenderIdentity& id) { id.sampler = "sobol"; }, "sampler sobol, this render independent"},
        {[](RenderIdentity& id) { id.integrator = "bsdf"; }, "integrator bsdf, this render path"},
        {[](RenderIdentity& id) { id.adaptive = AdaptiveSettings{0.02f, 16}; },
         "the checkpoint used adaptive sampling with threshold 0.02 and min_spp 16, this render no adaptive sampling"},
        {[](RenderIdentity& id) { id.content_hash ^= 1; }, "a different scene"},
    };
    for (const Case& c : cases) {
        RenderIdentity old = identity();
        c.change(old);
        std::string message = error_of([&] { check_checkpoint_matches("old.ckpt", old, identity()); });
        EXPECT_EQ(message.rfind("old.ckpt: cannot resume: ", 0), 0u) << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    }
}

TEST(Checkpoint, MissingFileOrFolderIsAClearError) {
    const fs::path missing = temp_file("missing.ckpt");
    EXPECT_NE(error_of([&] { read_checkpoint(missing); }).find("missing.ckpt: checkpoint not found"),
              std::string::npos);
    const fs::path folder = temp_file("folder.ckpt");
    fs::create_directories(folder);
    EXPECT_NE(error_of([&] { read_checkpoint(folder); }).find("is a folder"), std::string::npos);
}

TEST(Checkpoint, ForeignFilesAreRefused) {
    const fs::path file = temp_file("foreign.ckpt");
    write_bytes(file, "");
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("not a candela checkpoint: the file is empty"),
              std::string::npos);
    write_bytes(file, "PF\n5 3\n-1.0\n");  // an image, say
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("not a candela checkpoint"), std::string::npos);
}

TEST(Checkpoint, NewerFormatIsRefused) {
    const fs::path file = temp_file("newer.ckpt");
    write_checkpoint(file, identity(), state());
    std::string bytes = read_bytes(file);
    bytes[8] = 5;  // the format version's low byte
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("format version 5; this candela reads versions 1 to 4"),
              std::string::npos);
}

// A film with statistics (and weights), of an adaptive render: version 4, every value exact.
RenderState statistics_state() {
    RenderState s{Film(5, 3, true, {}, true), 17, 4};
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            const double i = double(y * 5 + x);
            s.film.sum(x, y) = {i / 3.0, std::ldexp(1.0 + i, -1060), -i * 1e300};
            s.film.weight(x, y) = -1.0 / 7.0 + i * 1e-3;
            s.film.squares(x, y) = {i / 11.0, i * i, 1e-300 * i};
            s.film.count(x, y) = 17.0 - i;
        }
    return s;
}

RenderIdentity adaptive_identity() {
    RenderIdentity id = identity();
    id.adaptive = AdaptiveSettings{0.015f, 24};
    return id;
}

std::vector<double> film_values(const Film& film) {
    std::vector<double> v(size_t(film.width() * film.height() * film.values_per_pixel()));
    film.read_region(PixelBounds{0, 0, film.width(), film.height()}, v.data());
    return v;
}

TEST(Checkpoint, StatisticsAndAdaptiveSettingsRoundTripInVersionFour) {
    const fs::path file = temp_file("statistics.ckpt");
    const RenderState s = statistics_state();
    write_checkpoint(file, adaptive_identity(), s);
    const std::string bytes = read_bytes(file);
    EXPECT_EQ(bytes[8], 4);
    // The header with the film's values and the adaptive settings, 17 values a pixel (sums, weight
    // sum, 13 statistics), the checksum.
    EXPECT_EQ(bytes.size(), kHeaderBytes + 12 + 15 * 17 * 8 + 8);
    const Checkpoint c = read_checkpoint(file);
    ASSERT_TRUE(c.state.film.has_statistics());
    ASSERT_TRUE(c.state.film.weighted());
    const std::vector<double> written = film_values(s.film), read = film_values(c.state.film);
    ASSERT_EQ(read.size(), written.size());
    EXPECT_EQ(std::memcmp(read.data(), written.data(), read.size() * sizeof(double)), 0);
    EXPECT_EQ(c.identity.adaptive, adaptive_identity().adaptive);
    EXPECT_EQ(c.state.samples_done, 17u);
    // Statistics without adaptive sampling (--target-error): version 4 too, no adaptive settings.
    write_checkpoint(file, identity(), s);
    EXPECT_EQ(read_bytes(file)[8], 4);
    EXPECT_FALSE(read_checkpoint(file).identity.adaptive.has_value());
    // An adaptive checkpoint refuses a render without adaptive sampling, and the other way round.
    EXPECT_NE(error_of([&] { check_checkpoint_matches("a.ckpt", adaptive_identity(), identity()); })
                  .find("the checkpoint used adaptive sampling with threshold 0.015 and min_spp 24, this render no "
                        "adaptive sampling"),
              std::string::npos);
    RenderIdentity other = adaptive_identity();
    other.adaptive->min_spp = 32;
    EXPECT_NE(error_of([&] { check_checkpoint_matches("a.ckpt", adaptive_identity(), other); })
                  .find("this render adaptive sampling with threshold 0.015 and min_spp 32"),
              std::string::npos);
}

// Flips the low and the high bit of each of the first `header` bytes of `file`, of every
// `stride`th byte after them and of the last 8 (the checksum), one at a time: reading each damaged
// file is an error that names the file.
void expect_every_flip_is_a_clear_error(const fs::path& file, size_t header, size_t stride) {
    const std::string bytes = read_bytes(file);
    for (size_t at = 0; at < bytes.size(); at += at < header || at + 8 >= bytes.size() ? 1 : stride) {
        for (int bit : {0, 7}) {
            std::string damaged = bytes;
            damaged[at] = char(damaged[at] ^ (1 << bit));
            write_bytes(file, damaged);
            std::string message = error_of([&] { read_checkpoint(file); });
            EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << at << ": " << message;
        }
    }
}

TEST(Checkpoint, EveryCorruptByteOfVersionFourIsAClearError) {
    const fs::path file = temp_file("corrupt4.ckpt");
    write_checkpoint(file, adaptive_identity(), statistics_state());
    expect_every_flip_is_a_clear_error(file, kHeaderBytes + 12, 13);
}

// The first builds with statistics kept 4 values per pixel and did not set the film-values word's
// bit 2; this build's decisions read the rays and prefix sums those lack, so such a checkpoint is
// refused with the reason (its length would not match anyway).
TEST(Checkpoint, StatisticsWithoutRaysAndPrefixSumsAreRefusedClearly) {
    const fs::path file = temp_file("old-statistics.ckpt");
    write_checkpoint(file, adaptive_identity(), statistics_state());
    std::string bytes = read_bytes(file);
    ASSERT_EQ(bytes[kHeaderBytes] & 6, 6);  // statistics, with rays and prefix sums
    bytes[kHeaderBytes] = char(bytes[kHeaderBytes] & ~4);
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("by an earlier build of candela, whose per-pixel "
                                                            "statistics lack the rays and prefix sums"),
              std::string::npos);
}

TEST(Checkpoint, WeightSumsRoundTripInVersionTwo) {
    const fs::path file = temp_file("weighted.ckpt");
    RenderState s = state();
    std::vector<double> weights(15);
    for (size_t i = 0; i < weights.size(); ++i) weights[i] = -1.0 / 7.0 + double(i) * 1e-3;
    s.film = Film(5, 3, s.film.sums(), weights);
    write_checkpoint(file, identity(), s);
    std::string bytes = read_bytes(file);
    EXPECT_EQ(bytes[8], 2);
    EXPECT_EQ(bytes.size(), kHeaderBytes + 15 * 4 * 8 + 8);
    const Checkpoint c = read_checkpoint(file);
    ASSERT_TRUE(c.state.film.weighted());
    EXPECT_EQ(std::memcmp(c.state.film.weights().data(), weights.data(), weights.size() * sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(c.state.film.sums().data(), s.film.sums().data(), 15 * sizeof(PixelSum)), 0);
    // Without weights the file is version 1, as before them.
    write_checkpoint(file, identity(), state());
    EXPECT_EQ(read_bytes(file)[8], 1);
    EXPECT_FALSE(read_checkpoint(file).state.film.weighted());
    // A version 1 file relabelled 2 is too short for its weights.
    bytes = read_bytes(file);
    bytes[8] = 2;
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("truncated checkpoint"), std::string::npos);
}

TEST(Checkpoint, EveryTruncationIsAClearError) {
    const fs::path file = temp_file("truncated.ckpt");
    write_checkpoint(file, identity(), state());
    const std::string bytes = read_bytes(file);
    // Every length within the header, every seventh within the sums.
    for (size_t size = 1; size < bytes.size(); size += size < kHeaderBytes ? 1 : 7) {
        write_bytes(file, bytes.substr(0, size));
        std::string message = error_of([&] { read_checkpoint(file); });
        EXPECT_EQ(message.rfind(file.string() + ": truncated checkpoint", 0), 0u) << size << ": " << message;
    }
    write_bytes(file, bytes + "x");
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("1 more than a 5x3 checkpoint has"), std::string::npos);
}

TEST(Checkpoint, EveryCorruptByteIsAClearError) {
    // Flipping the low or the high bit of any header byte, of every eleventh byte of the sums, or of
    // any checksum byte: the magic, the version, a name's length, the size or the checksum
    // catches it; never a crash or a silently wrong film.
    const fs::path file = temp_file("corrupt.ckpt");
    write_checkpoint(file, identity(), state());
    expect_every_flip_is_a_clear_error(file, kHeaderBytes, 11);
}

TEST(Checkpoint, HugeClaimedSizeIsRefusedWithoutAllocating) {
    // A header claiming 32768 x 32768 pixels in a file of a few hundred bytes: truncated, found
    // before any film is allocated.
    const fs::path file = temp_file("huge.ckpt");
    RenderIdentity id = identity();
    write_checkpoint(file, id, state());
    std::string bytes = read_bytes(file);
    const size_t width_at = 8 + 4 + (4 + 5) + (4 + 4) + (4 + 11) + 8 + 8;
    for (size_t i : {width_at, width_at + 4}) {
        bytes[i] = 0;
        bytes[i + 1] = char(0x80);  // 32768
    }
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_checkpoint(file); }).find("a 32768x32768 checkpoint has"), std::string::npos);
}

}  // namespace
}  // namespace candela
