// A keyed hash (a MAC) for what fxport reads back from a folder others might write: the compile
// cache. SipHash-2-4 (Aumasson and Bernstein), a PRF: without the key, nobody can make text whose
// hash matches, unlike the unkeyed FNV of contentHash(), where anyone can compute a matching sum or
// craft a collision.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace fxport::xlate {

using SipKey = std::array<std::uint8_t, 16>;

// SipHash-2-4 of `data` under `key` (the reference algorithm; 64-bit output).
std::uint64_t sipHash24(const SipKey& key, std::string_view data);

// 128 bits as 32 hex digits: SipHash-2-4 under two independent halves of a 32-byte secret.
struct CacheSecret {
    SipKey first{}, second{};
};
std::string keyedHash(const CacheSecret& secret, std::string_view data);

}  // namespace fxport::xlate
