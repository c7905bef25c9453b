#include "candela/scene/enum_names.h"

#include <gtest/gtest.h>

#include <array>

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(EnumNames, IntegratorNamesRoundTrip) {
    ASSERT_EQ(integrator_type_names().size(), 8u);
    for (std::string_view name : integrator_type_names()) {
        std::optional<IntegratorType> type = parse_integrator_type(name);
        ASSERT_TRUE(type) << name;
        EXPECT_EQ(integrator_type_name(*type), name);
    }
    EXPECT_EQ(parse_integrator_type("path"), IntegratorType::kPath);
    EXPECT_EQ(parse_integrator_type("bsdf"), IntegratorType::kBsdf);
    EXPECT_EQ(parse_integrator_type("whitted"), IntegratorType::kWhitted);
    EXPECT_EQ(parse_integrator_type("ao"), IntegratorType::kAo);
    EXPECT_EQ(parse_integrator_type("normals"), IntegratorType::kNormals);
    EXPECT_EQ(parse_integrator_type("volpath"), IntegratorType::kVolPath);
    EXPECT_EQ(integrator_type_name(IntegratorType::kDepth), "depth");
    EXPECT_EQ(integrator_type_name(IntegratorType::kAlbedo), "albedo");
}

TEST(EnumNames, FilmNamesRoundTrip) {
    for (std::string_view name : filter_type_names())
        EXPECT_EQ(filter_type_name(parse_filter_type(name).value()), name);
    for (std::string_view name : tonemap_names())
        EXPECT_EQ(tonemap_name(parse_tonemap(name).value()), name);
    for (std::string_view name : transfer_names())
        EXPECT_EQ(transfer_name(parse_transfer(name).value()), name);
    for (std::string_view name : light_selection_names())
        EXPECT_EQ(light_selection_name(parse_light_selection(name).value()), name);
    EXPECT_EQ(parse_filter_type("smallpt"), FilterType::kSmallpt);
    EXPECT_EQ(parse_filter_type("gaussian"), FilterType::kGaussian);
    EXPECT_EQ(parse_tonemap("aces"), Tonemap::kAces);
    EXPECT_EQ(parse_tonemap("reinhard"), Tonemap::kReinhard);
    EXPECT_EQ(parse_transfer("gamma"), Transfer::kGamma);
}

TEST(EnumNames, MetalNamesRoundTripInTheTablesOrder) {
    ASSERT_EQ(metal_names().size(), static_cast<size_t>(kMetalCount));
    for (std::string_view name : metal_names()) EXPECT_EQ(metal_name(parse_metal(name).value()), name);
    EXPECT_EQ(parse_metal("Au"), Metal::kAu);
    EXPECT_EQ(parse_metal("CuZn"), Metal::kCuZn);
    EXPECT_EQ(metal_name(Metal::kTi), "Ti");
    EXPECT_FALSE(parse_metal("au"));  // chemical symbols, case-sensitive
    EXPECT_EQ(names_list(metal_names()), "Ag, Al, Au, Cr, Cu, CuZn, Fe, Ti");
}

TEST(EnumNames, UnknownNamesParseToNothing) {
    EXPECT_FALSE(parse_integrator_type("bdpt"));
    EXPECT_FALSE(parse_integrator_type("AO"));  // names are case-sensitive
    EXPECT_FALSE(parse_filter_type(""));
    EXPECT_FALSE(parse_tonemap("filmic"));
    EXPECT_FALSE(parse_transfer("linear"));
}

TEST(EnumNames, NamesListIsSortedAndCommaSeparated) {
    EXPECT_EQ(names_list(integrator_type_names()), "albedo, ao, bsdf, depth, normals, path, volpath, whitted");
    EXPECT_EQ(names_list(light_selection_names()), "bvh, power, uniform");
    EXPECT_EQ(names_list(filter_type_names()), "box, gaussian, smallpt, tent");
    EXPECT_EQ(names_list(tonemap_names()), "aces, clamp, exposure, reinhard");
    EXPECT_EQ(names_list(transfer_names()), "gamma, srgb");
    EXPECT_EQ(names_list({}), "");
}

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(edit_distance("albedo", "albedo"), 0u);
    EXPECT_EQ(edit_distance("albdo", "albedo"), 1u);     // insertion
    EXPECT_EQ(edit_distance("radiuss", "radius"), 1u);   // deletion
    EXPECT_EQ(edit_distance("radios", "radius"), 1u);    // substitution
    EXPECT_EQ(edit_distance("shpere", "sphere"), 1u);    // adjacent swap
    EXPECT_EQ(edit_distance("", "fov"), 3u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("materails", "materials"), 1u);
}

TEST(ClosestName, SuggestsNearMissesOnly) {
    const std::array<std::string_view, 5> keys = {"type", "albedo", "ior", "tint", "radius"};
    EXPECT_EQ(closest_name("albdo", keys), "albedo");
    EXPECT_EQ(closest_name("radus", keys), "radius");
    EXPECT_EQ(closest_name("tnit", keys), "tint");
    EXPECT_EQ(closest_name("albedo", keys), "albedo");
    EXPECT_FALSE(closest_name("emission", keys));
    // Two edits could turn "xy" into "ior"'s neighbours, but that is no near miss.
    EXPECT_FALSE(closest_name("xy", keys));
    EXPECT_FALSE(closest_name("anything", {}));
}

TEST(ClosestName, TiesGoToTheEarlierCandidate) {
    const std::array<std::string_view, 2> box_first = {"box", "bot"};
    const std::array<std::string_view, 2> bot_first = {"bot", "box"};
    EXPECT_EQ(closest_name("bo", box_first), "box");
    EXPECT_EQ(closest_name("bo", bot_first), "bot");
}

}  // namespace
}  // namespace candela
