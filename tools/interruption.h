// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Interruption of the point_set_curvatures tool: the state its SIGINT/SIGTERM handler sets
// (every phase polls it at its progress reports and stops), the temporary output that a second
// signal removes, the phase running, and the tests' hook raising a signal at a phase's start.

#ifndef POINT_SET_CURVATURES_TOOL_INTERRUPTION_H
#define POINT_SET_CURVATURES_TOOL_INTERRUPTION_H

#include <csignal>
#include <string>

namespace psc_tool {

// Set by the first SIGINT or SIGTERM.
extern volatile std::sig_atomic_t interrupted;
// The signal that interrupted the run (SIGINT or SIGTERM): the exit status is 128 + it.
extern volatile std::sig_atomic_t interrupt_signal;
// The temporary output file, removed by a second Ctrl-C (a fixed buffer: the handler may only
// call async-signal-safe functions). Empty when there is none.
extern char temporary_output_path[4096];

// The phase running (its name in the progress bar), named in the message of an interrupted
// run: the phase that stopped.
extern std::string current_phase;

// Test hook (test_tool): PSC_TOOL_TEST_SIGNAL=INT@NAME, TERM@NAME or KILL@NAME raises SIGINT,
// SIGTERM or SIGKILL when the first phase whose name starts with NAME begins ('*' in NAME: any
// text, as in "tile *curvatures"; NAME#N: the N-th such phase), so that a test can check that
// every phase stops at the signal (within a progress report: about 1% of its work, 0.25 s),
// and what a run killed in a phase leaves behind.
void test_signal_at_phase_start(const std::string& phase);

}  // namespace psc_tool

// The first Ctrl-C (or SIGTERM) cancels the current phase at its next progress report; a
// second one removes the temporary output and exits at once. Exit status 128 + the signal,
// as a shell reports a process the signal killed: 130 for SIGINT, 143 for SIGTERM.
extern "C" void on_interrupt(int signal);

#endif
