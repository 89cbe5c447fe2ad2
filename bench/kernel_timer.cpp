// A Kokkos Tools library that times every kernel by its label and prints,
// when Kokkos finalizes, each label's share of the kernel time, its mean
// time per call and its number of calls (to standard error). Used by
// bench/kernel_profile.sh; build: g++ -O2 -shared -fPIC kernel_timer.cpp.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

struct Total
{
    double seconds = 0.0;
    long calls = 0;
};

std::map<std::string, Total> totals;
std::unordered_map<std::uint64_t, std::pair<std::string, Clock::time_point>>
    running;
std::uint64_t next_id = 0;

void begin( const char* label, std::uint64_t* id )
{
    *id = next_id++;
    running[*id] = { label, Clock::now() };
}

void end( const std::uint64_t id )
{
    const auto it = running.find( id );
    if ( it == running.end() )
        return;
    Total& total = totals[it->second.first];
    total.seconds +=
        std::chrono::duration<double>( Clock::now() - it->second.second )
            .count();
    ++total.calls;
    running.erase( it );
}
} // namespace

extern "C"
{
    void kokkosp_init_library( int, std::uint64_t, std::uint32_t, void* ) {}
    void kokkosp_begin_parallel_for( const char* label, std::uint32_t,
                                     std::uint64_t* id )
    {
        begin( label, id );
    }
    void kokkosp_end_parallel_for( std::uint64_t id ) { end( id ); }
    void kokkosp_begin_parallel_reduce( const char* label, std::uint32_t,
                                        std::uint64_t* id )
    {
        begin( label, id );
    }
    void kokkosp_end_parallel_reduce( std::uint64_t id ) { end( id ); }
    void kokkosp_begin_parallel_scan( const char* label, std::uint32_t,
                                      std::uint64_t* id )
    {
        begin( label, id );
    }
    void kokkosp_end_parallel_scan( std::uint64_t id ) { end( id ); }

    void kokkosp_finalize_library()
    {
        std::vector<std::pair<std::string, Total>> rows( totals.begin(),
                                                         totals.end() );
        std::sort( rows.begin(), rows.end(),
                   []( const auto& a, const auto& b )
                   { return a.second.seconds > b.second.seconds; } );
        double sum = 0.0;
        for ( const auto& row : rows )
            sum += row.second.seconds;
        std::fprintf( stderr, "kernel time: %.3f s\n", sum );
        std::fprintf( stderr, "| kernel | share | us per call | calls |\n" );
        std::fprintf( stderr, "|---|--:|--:|--:|\n" );
        for ( const auto& [label, total] : rows )
            if ( total.seconds > 0.002 * sum )
                std::fprintf( stderr, "| %s | %.1f %% | %.1f | %ld |\n",
                              label.c_str(), 100.0 * total.seconds / sum,
                              1e6 * total.seconds / total.calls, total.calls );
    }
}
