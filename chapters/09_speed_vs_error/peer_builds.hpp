/// @file
/// Why each optional peer library was not built (CMake's reason), or nullptr when it was. Only
/// for the chapter's own library, which CMake gives the TUTORIAL_*_SKIPPED_BECAUSE definitions.
#pragma once

namespace tri::ch09 {

#if TUTORIAL_WITH_OSMESA
inline constexpr const char* llvmpipe_not_built = nullptr;
#else
inline constexpr const char* llvmpipe_not_built = TUTORIAL_LLVMPIPE_SKIPPED_BECAUSE;
#endif
#if TUTORIAL_WITH_PIXMAN
inline constexpr const char* pixman_not_built = nullptr;
#else
inline constexpr const char* pixman_not_built = TUTORIAL_PIXMAN_SKIPPED_BECAUSE;
#endif
#if TUTORIAL_WITH_CAIRO
inline constexpr const char* cairo_not_built = nullptr;
#else
inline constexpr const char* cairo_not_built = TUTORIAL_CAIRO_SKIPPED_BECAUSE;
#endif
#if TUTORIAL_WITH_AGG
inline constexpr const char* agg_not_built = nullptr;
#else
inline constexpr const char* agg_not_built = TUTORIAL_AGG_SKIPPED_BECAUSE;
#endif

}  // namespace tri::ch09
