#pragma once
// The viewer's background work (loading, vertex normals, BVH builds, the
// OpenMesh check, comparisons) runs below the UI thread's priority, so that
// a frame is not held up by it. Linux groups a session's processes
// (autogroup): the lower priority weighs only against the viewer's own
// threads, not against other programs, so the work is no slower while the
// UI thread sleeps, which is nearly always.

namespace meshtrace::viewer {

inline constexpr int kBackgroundNice = 10;

// Gives the calling thread kBackgroundNice (Linux gives each thread its own).
void runThisThreadInBackground();

// From now on, for the rest of the process, TBB's worker threads run at
// kBackgroundNice; threads that call into TBB themselves (the UI thread, a
// task's thread) keep theirs. Call once, early in main.
void runTbbWorkersInBackground();

}  // namespace meshtrace::viewer
