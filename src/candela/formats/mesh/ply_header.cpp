#include "candela/formats/mesh/ply_header.h"

#include <fmt/format.h>

#include <charconv>
#include <utility>

#include "candela/core/error.h"

namespace candela {
namespace {

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

PlyType parse_type(std::string_view word, const std::string& file, int line) {
    for (const PlyTypeName& n : kPlyTypeNames)
        if (n.name == word) return n.type;
    fail_in_file(file, line,
            fmt::format("unknown PLY property type \"{}\"; expected one of: char, uchar, short, "
                        "ushort, int, uint, float, double, int8, uint8, int16, uint16, int32, "
                        "uint32, float32, float64",
                        word));
}

void parse_property(const std::vector<std::string_view>& w, PlyElement& element, const std::string& file,
                    int line) {
    PlyProperty p;
    if (w.size() == 5 && w[1] == "list") {
        p.list_count = parse_type(w[2], file, line);
        if (!is_integer(*p.list_count))
            fail_in_file(file, line, fmt::format("a list count must have an integer type, got \"{}\"", w[2]));
        p.type = parse_type(w[3], file, line);
        p.name = std::string(w[4]);
    } else if (w.size() == 3 && w[1] != "list") {
        p.type = parse_type(w[1], file, line);
        p.name = std::string(w[2]);
    } else {
        fail_in_file(file, line, "expected \"property TYPE NAME\" or \"property list COUNT_TYPE ITEM_TYPE NAME\"");
    }
    for (const PlyProperty& q : element.properties)
        if (q.name == p.name)
            fail_in_file(file, line,
                    fmt::format("element \"{}\" declares property \"{}\" twice", element.name, p.name));
    element.properties.push_back(std::move(p));
}

}  // namespace

uint64_t min_record_bytes(const PlyElement& e, PlyFormat format) {
    uint64_t bytes = 0;
    for (const PlyProperty& p : e.properties) {
        if (format == PlyFormat::kAscii)
            bytes += 2;
        else
            bytes += type_size(p.list_count ? *p.list_count : p.type);
    }
    return bytes;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& file) {
    if (bytes.substr(0, 3) != "ply" || (bytes.size() > 3 && bytes[3] != '\n' && bytes[3] != '\r'))
        fail_in_file(file, 1, "not a PLY file: expected \"ply\" on the first line");
    PlyHeader header;
    bool has_format = false;
    size_t pos = 0;
    int line = 0;
    while (pos < bytes.size()) {
        size_t newline = bytes.find('\n', pos);
        size_t stop = newline == std::string_view::npos ? bytes.size() : newline;
        std::string_view text = bytes.substr(pos, stop - pos);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        pos = newline == std::string_view::npos ? bytes.size() : newline + 1;
        ++line;
        if (line == 1) continue;  // "ply", checked above

        const std::vector<std::string_view> w = split_words(text);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "format") {
            if (w.size() != 3) fail_in_file(file, line, "expected \"format FORMAT 1.0\"");
            if (w[1] == "ascii")
                header.format = PlyFormat::kAscii;
            else if (w[1] == "binary_little_endian")
                header.format = PlyFormat::kBinaryLittleEndian;
            else if (w[1] == "binary_big_endian")
                header.format = PlyFormat::kBinaryBigEndian;
            else
                fail_in_file(file, line,
                        fmt::format("unknown PLY format \"{}\"; expected one of: ascii, "
                                    "binary_big_endian, binary_little_endian",
                                    w[1]));
            if (w[2] != "1.0")
                fail_in_file(file, line, fmt::format("unsupported PLY version \"{}\"; expected 1.0", w[2]));
            has_format = true;
        } else if (w[0] == "element") {
            if (w.size() != 3) fail_in_file(file, line, "expected \"element NAME COUNT\"");
            PlyElement e;
            e.name = std::string(w[1]);
            e.line = line;
            auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
            if (ec != std::errc() || end != w[2].data() + w[2].size())
                fail_in_file(file, line,
                        fmt::format("expected an element count (an integer >= 0), got \"{}\"", w[2]));
            for (const PlyElement& other : header.elements)
                if (other.name == e.name)
                    fail_in_file(file, line, fmt::format("element \"{}\" is declared twice", e.name));
            header.elements.push_back(std::move(e));
        } else if (w[0] == "property") {
            if (header.elements.empty()) fail_in_file(file, line, "a property before any element");
            parse_property(w, header.elements.back(), file, line);
        } else if (w[0] == "end_header") {
            if (!has_format) fail_in_file(file, line, "the header has no \"format\" line");
            header.data_offset = pos;
            header.end_line = line;
            return header;
        } else {
            fail_in_file(file, line,
                    fmt::format("unknown PLY header keyword \"{}\"; expected one of: comment, "
                                "element, end_header, format, obj_info, property",
                                w[0]));
        }
    }
    fail_in_file(file, line, "the PLY header has no \"end_header\" line");
}

// The sum cannot overflow: each term is bounded by the data size before it is added.
void check_ply_counts_fit(const PlyHeader& header, size_t data_bytes, const std::string& file) {
    // The last ascii value needs no separator after it.
    const uint64_t available = data_bytes + (header.format == PlyFormat::kAscii ? 1 : 0);
    uint64_t needed = 0;
    for (const PlyElement& e : header.elements) {
        const uint64_t min_bytes = min_record_bytes(e, header.format);
        if (min_bytes == 0) continue;
        if (e.count > (available - needed) / min_bytes)
            fail_in_file(file, e.line,
                    fmt::format("element \"{}\" declares {} records of at least {} bytes each, but the "
                                "data after the header has only {} bytes (file truncated?)",
                                e.name, e.count, min_bytes, data_bytes));
        needed += e.count * min_bytes;
    }
}

}  // namespace candela
