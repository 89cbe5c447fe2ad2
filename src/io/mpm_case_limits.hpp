#ifndef MPM_CASE_LIMITS_HPP
#define MPM_CASE_LIMITS_HPP

#include <cstddef>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Limits of the case reader: a case file beyond them is refused before it
// is parsed or expanded, so `check` ends within seconds and bounded memory
// on any input. Internal to src/io/mpm_case_*.
//---------------------------------------------------------------------------//

//! Largest case file (or included file), bytes.
constexpr std::size_t max_case_file_bytes = 8u << 20;

//! Largest total of a case file and every file it includes, bytes.
constexpr std::size_t max_case_total_bytes = 16u << 20;

//! Most included files (counting repeats) of one case.
constexpr int max_include_files = 64;

//! Included files may include others up to this depth.
constexpr int max_include_depth = 8;

//! Deepest nesting of keys, arrays and inline tables (toml++ recurses on
//! it and overflows the stack at some 35,000 levels).
constexpr int max_nesting_depth = 64;

//! Longest key or name (material, stage, probe and case names).
constexpr std::size_t max_name_length = 128;

//! Longest free text (case.description).
constexpr std::size_t max_text_length = 4096;

//! Most vertices of a body polygon (the self-intersection test is
//! quadratic, every point is tested against every edge).
constexpr std::size_t max_polygon_vertices = 2000;

//! Most points of any other point list (polylines, time functions).
constexpr std::size_t max_list_points = 100000;

//! Most grid cells (nx * ny), far below the int range of node indices.
constexpr long long max_grid_cells = 100000000;

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_LIMITS_HPP
