/// @file
/// The 128-bit integers the exact paths fall back on when 64 bits cannot hold a product: one
/// alias for the whole book (GCC and Clang provide __int128 on 64-bit targets).
#pragma once

namespace tri {

__extension__ using Int128 = __int128;
__extension__ using UInt128 = unsigned __int128;

}  // namespace tri
