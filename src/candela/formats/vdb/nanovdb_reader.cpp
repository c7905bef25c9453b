// NanoVDB's files, read by our own code: the table of contents (nanovdb_file.cpp) says where the
// named grid lies; its buffer is read only after the budget allows it, and decoded by
// nanovdb_tree.cpp. Compressed grids (zip, blosc) are refused rather than inflated.
#include "candela/formats/vdb/nanovdb_reader.h"

#include <fmt/format.h>

#include "candela/core/error.h"
#include "candela/formats/vdb/nanovdb_file.h"
#include "candela/formats/vdb/nanovdb_layout.h"
#include "candela/formats/vdb/nanovdb_tree.h"
#include "candela/scene/memory_budget.h"

namespace candela {
namespace {

std::string quoted_names(const std::vector<NanoVdbGridEntry>& grids) {
    std::string names;
    for (const NanoVdbGridEntry& g : grids) names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", g.name);
    return names;
}

}  // namespace

VolumeGrid read_nanovdb_grid(const std::filesystem::path& path, std::string_view grid_name, MemoryBudget& budget) {
    NanoVdbFile f = open_nanovdb_file(path);
    const NanoVdbGridEntry* entry = nullptr;
    for (const NanoVdbGridEntry& g : f.grids)
        if (g.name == grid_name) {
            entry = &g;
            break;
        }
    if (!entry) {
        if (f.grids.empty())
            fail_in_file(f.file, fmt::format("no grid named \"{}\": the NanoVDB file has no grids", grid_name));
        fail_in_file(f.file,
                     fmt::format("no grid named \"{}\"; the NanoVDB file has: {}", grid_name, quoted_names(f.grids)));
    }
    if (entry->codec != nanovdb_layout::kCodecNone)
        fail_in_file(f.file,
                     fmt::format("grid \"{}\" is compressed ({}); candela reads uncompressed NanoVDB files only: write "
                                 "it again with codec none (nanovdb::io::Codec::NONE)",
                                 entry->name, nanovdb_codec_name(entry->codec)));
    if (entry->grid_type != nanovdb_layout::kGridTypeFloat)
        fail_in_file(f.file, fmt::format("grid \"{}\" holds {} values; candela reads float grids only", entry->name,
                                         nanovdb_type_name(entry->grid_type)));
    if (auto refused = budget.charge(0, fmt::format("reading NanoVDB grid \"{}\"", entry->name), entry->grid_size))
        fail_in_file(f.file, *refused);
    const std::string bytes = read_nanovdb_grid_bytes(f, *entry);
    return decode_nanovdb_float_grid(bytes, f.file, entry->name, budget);
}

std::vector<std::string> nanovdb_grid_names(const std::filesystem::path& path) {
    std::vector<std::string> names;
    for (const NanoVdbGridEntry& g : open_nanovdb_file(path).grids) names.push_back(g.name);
    return names;
}

}  // namespace candela
