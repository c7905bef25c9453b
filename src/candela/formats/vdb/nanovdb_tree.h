#pragma once
// Decodes the buffer of one NanoVDB float grid (GridData, TreeData, root, internal nodes, leaves;
// nanovdb_layout.h) into a dense VolumeGrid, checking every offset before it follows it.
#include <string>
#include <string_view>

#include "candela/formats/vdb/volume_grid.h"

namespace candela {

class MemoryBudget;

// `bytes`: the grid's whole buffer; `file` and `name` name it in errors. Charges the dense block
// to `budget` (with `bytes` as transient) before allocating it. Throws SceneError for a corrupt
// buffer, a refused budget, a singular or non-finite map, or a non-finite value.
VolumeGrid decode_nanovdb_float_grid(std::string_view bytes, const std::string& file, const std::string& name,
                                     MemoryBudget& budget);

}  // namespace candela
