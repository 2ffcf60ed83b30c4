#pragma once
/// \file
/// The library's one way of running independent work items in parallel: a
/// dynamically scheduled loop over indices on a few threads (relaxations of
/// samples, members of a family, pairs of states). Each item must be
/// independent of the others except through state the body protects itself.
#include <cstddef>
#include <functional>

namespace ek {

/// Calls body(i) for every i in [0, count) on up to `jobs` threads, the
/// calling thread among them, handing out the indices in increasing order as
/// threads become free. When a body throws, no further index is handed out;
/// after every thread has finished, the exception of the smallest failed
/// index is rethrown. With jobs <= 1 (or count <= 1) the loop runs in order
/// on the calling thread.
void parallel_for(std::size_t count, int jobs, const std::function<void(std::size_t)>& body);

}  // namespace ek
