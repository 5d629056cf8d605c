#include "effect/keyed_hash.h"

#include <cstdio>
#include <cstring>

namespace fxport::xlate {

namespace {

constexpr std::uint64_t rotl(std::uint64_t x, int b) { return (x << b) | (x >> (64 - b)); }

std::uint64_t le64(const std::uint8_t* p) {
    std::uint64_t v = 0;
    for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
    return v;
}

struct SipState {
    std::uint64_t v0, v1, v2, v3;
    void round() {
        v0 += v1, v1 = rotl(v1, 13), v1 ^= v0, v0 = rotl(v0, 32);
        v2 += v3, v3 = rotl(v3, 16), v3 ^= v2;
        v0 += v3, v3 = rotl(v3, 21), v3 ^= v0;
        v2 += v1, v1 = rotl(v1, 17), v1 ^= v2, v2 = rotl(v2, 32);
    }
    void absorb(std::uint64_t m) {  // two compression rounds per word
        v3 ^= m;
        round();
        round();
        v0 ^= m;
    }
};

}  // namespace

std::uint64_t sipHash24(const SipKey& key, std::string_view data) {
    const std::uint64_t k0 = le64(key.data()), k1 = le64(key.data() + 8);
    SipState s{k0 ^ 0x736f6d6570736575ull, k1 ^ 0x646f72616e646f6dull, k0 ^ 0x6c7967656e657261ull, k1 ^ 0x7465646279746573ull};
    const auto* p = reinterpret_cast<const std::uint8_t*>(data.data());
    size_t whole = data.size() & ~size_t{7};
    for (size_t i = 0; i < whole; i += 8) s.absorb(le64(p + i));
    // The last word: the remaining bytes and the length's low byte on top.
    std::uint8_t last[8] = {};
    std::memcpy(last, p + whole, data.size() - whole);
    last[7] = static_cast<std::uint8_t>(data.size());
    s.absorb(le64(last));
    s.v2 ^= 0xff;  // four finalisation rounds
    for (int i = 0; i < 4; ++i) s.round();
    return s.v0 ^ s.v1 ^ s.v2 ^ s.v3;
}

std::string keyedHash(const CacheSecret& secret, std::string_view data) {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(sipHash24(secret.first, data)),
                  static_cast<unsigned long long>(sipHash24(secret.second, data)));
    return buf;
}

}  // namespace fxport::xlate
