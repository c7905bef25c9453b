#include "candela/distributed/tile_messages.h"

#include <cstring>

namespace candela {

void MessageWriter::put(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    bytes_.insert(bytes_.end(), p, p + n);
}

std::optional<TileMessageType> MessageReader::type() {
    const uint8_t t = u8();
    if (failed_ || t < uint8_t(TileMessageType::kRequest) || t > uint8_t(TileMessageType::kEnd)) return std::nullopt;
    return TileMessageType(t);
}

template <class T>
T MessageReader::get() {
    T v{};
    if (failed_ || bytes_.size() - at_ < sizeof(T)) {
        failed_ = true;
        return v;
    }
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
}

bool MessageReader::doubles(double* out, size_t count) {
    const size_t n = count * sizeof(double);
    if (failed_ || bytes_.size() - at_ < n) {
        failed_ = true;
        return false;
    }
    std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
    return true;
}

template uint8_t MessageReader::get<uint8_t>();
template uint32_t MessageReader::get<uint32_t>();
template int32_t MessageReader::get<int32_t>();
template uint64_t MessageReader::get<uint64_t>();
template double MessageReader::get<double>();

}  // namespace candela
