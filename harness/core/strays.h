// Processes a tracer or build step left behind outside its process group (a `setsid` daemon, a
// double fork). Killing the group cannot reach them, so raygate makes itself a child subreaper
// (Linux prctl PR_SET_CHILD_SUBREAPER): orphans of its descendants are re-parented to raygate
// instead of to PID 1, and after each child ends raygate kills and reaps every child of its own
// that it did not start and has not reaped (a stray).
//
// Why not one cgroup per child: creating cgroups needs a delegated, writable cgroup v2 tree,
// which unprivileged users and most CI containers do not have; the subreaper needs no privilege
// and works on every Linux since 3.4. Its limit: a stray that escapes before its parent exits
// is caught only once that parent has exited, which a child raygate waits for always does.
#pragma once

#include <mutex>

namespace raygate {

// Makes this process the subreaper of its descendants. Returns false where the platform does
// not allow it (then strays re-parent to PID 1 and are not swept).
bool become_subreaper();

// Kills (SIGKILL, with their process groups) and reaps every child of this process that is not
// a registered live child (core/interrupt.h), repeating until none is left, since a killed
// stray's own children re-parent to us in turn. Does nothing unless this process is a
// subreaper. Returns how many it swept.
int sweep_stray_children();

// Held while a child is started and registered, and while sweeping, so a sweep never takes a
// child that was just started for a stray.
std::mutex& child_table_mutex();

}  // namespace raygate
