// candela_make_mesh --triangles N OUT.ply: writes a displaced sphere of at least N triangles as
// binary little-endian PLY (float x y z; list uchar int vertex_indices), for the mesh-heavy
// benchmark and the triangle-count scaling runs. Generated at run time because a 10M-triangle
// mesh is 190 MB: not something to keep in the repository.
//
// The sphere is a cube with each face an n x n grid (12 n^2 triangles), pushed out to the unit
// sphere and displaced along the normal by a sum of products of sines, so every triangle is
// small and the surface has relief at all scales. Grid coordinates are computed from integers
// the same way on every face, so vertices on shared cube edges coincide exactly: watertight. The
// output depends only on n: the same file on every machine, so references stay valid.
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// Radius of the displaced surface in direction (x, y, z), |(x, y, z)| = 1.
double radius(double x, double y, double z) {
    double r = 1.0;
    r += 0.08 * std::sin(5.0 * x + 1.0) * std::sin(5.0 * y + 2.0) * std::sin(5.0 * z + 3.0);
    r += 0.03 * std::sin(23.0 * x) * std::sin(19.0 * y + 1.0) * std::sin(29.0 * z + 0.5);
    r += 0.01 * std::sin(97.0 * x + 0.3) * std::sin(89.0 * y) * std::sin(101.0 * z + 1.7);
    return r;
}

struct Writer {
    std::FILE* f;
    std::vector<char> buffer;
    bool ok = true;
    template <class T>
    void put(T v) {
        const char* p = reinterpret_cast<const char*>(&v);
        buffer.insert(buffer.end(), p, p + sizeof(T));
        if (buffer.size() > (1u << 20)) flush();
    }
    void flush() {
        ok = ok && std::fwrite(buffer.data(), 1, buffer.size(), f) == buffer.size();
        buffer.clear();
    }
};

int make(uint64_t min_triangles, const std::string& out) {
    const auto n = uint32_t(std::ceil(std::sqrt(double(min_triangles) / 12.0)));
    if (n < 1 || n > 10000) {
        fmt::print(stderr, "candela_make_mesh: --triangles must be in 1..1.2e9\n");
        return 2;
    }
    const uint64_t side = n + 1;
    const uint64_t vertices = 6 * side * side, triangles = 12 * uint64_t(n) * n;
    std::FILE* f = std::fopen(out.c_str(), "wb");
    if (!f) {
        fmt::print(stderr, "candela_make_mesh: cannot create {}\n", out);
        return 2;
    }
    Writer w{f, {}};
    std::string header = fmt::format(
        "ply\nformat binary_little_endian 1.0\ncomment candela_make_mesh: displaced cube sphere, n = {}\n"
        "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
        "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        n, vertices, triangles);
    w.buffer.assign(header.begin(), header.end());

    auto coord = [n](uint32_t i) { return double(2 * int64_t(i) - int64_t(n)) / double(n); };
    // Face (axis k, sign s): p[k] = s, p[k+1] = coord(i), p[k+2] = coord(j).
    for (int k = 0; k < 3; ++k)
        for (int s = -1; s <= 1; s += 2)
            for (uint32_t j = 0; j <= n; ++j)
                for (uint32_t i = 0; i <= n; ++i) {
                    double p[3];
                    p[k] = s;
                    p[(k + 1) % 3] = coord(i);
                    p[(k + 2) % 3] = coord(j);
                    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                    const double x = p[0] / len, y = p[1] / len, z = p[2] / len, r = radius(x, y, z);
                    w.put(float(x * r));
                    w.put(float(y * r));
                    w.put(float(z * r));
                }
    // Counter-clockwise seen from outside: (i, j) -> (i+1, j) -> (i+1, j+1) faces +e_k, so the
    // negative faces take the reverse order.
    for (int face = 0; face < 6; ++face) {
        const bool positive = face % 2 == 1;
        const auto base = uint32_t(uint64_t(face) * side * side);
        auto v = [&](uint32_t i, uint32_t j) { return int32_t(base + j * side + i); };
        auto tri = [&](int32_t a, int32_t b, int32_t c) {
            w.put(uint8_t(3));
            w.put(a);
            if (positive) {
                w.put(b);
                w.put(c);
            } else {
                w.put(c);
                w.put(b);
            }
        };
        for (uint32_t j = 0; j < n; ++j)
            for (uint32_t i = 0; i < n; ++i) {
                tri(v(i, j), v(i + 1, j), v(i + 1, j + 1));
                tri(v(i, j), v(i + 1, j + 1), v(i, j + 1));
            }
    }
    w.flush();
    const bool ok = (std::fclose(f) == 0) && w.ok;
    if (!ok) {
        fmt::print(stderr, "candela_make_mesh: cannot write {}\n", out);
        return 1;
    }
    fmt::print("{}: {} triangles, {} vertices\n", out, triangles, vertices);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4 || std::string(argv[1]) != "--triangles") {
        fmt::print(stderr, "usage: candela_make_mesh --triangles N OUT.ply\n");
        return 2;
    }
    char* end = nullptr;
    const unsigned long long n = std::strtoull(argv[2], &end, 10);
    if (*end != '\0' || n == 0) {
        fmt::print(stderr, "candela_make_mesh: --triangles: expected a positive integer, got \"{}\"\n", argv[2]);
        return 2;
    }
    return make(n, argv[3]);
}
