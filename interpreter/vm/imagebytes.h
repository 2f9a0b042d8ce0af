#pragma once

#include <cstdint>
#include <cstring>

// Reading and writing a value at any byte of the memory image: variables are packed, so a
// memcpy (no alignment, no aliasing assumptions) is the one correct way, and compiles to a move.
namespace iec::interp::image {

template<typename T>
T load(const std::uint8_t *p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template<typename T>
void store(std::uint8_t *p, T v)
{
    std::memcpy(p, &v, sizeof v);
}

} // namespace iec::interp::image
