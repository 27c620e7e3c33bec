// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See interruption.h.

#include "interruption.h"

#include <unistd.h>

#include <cstdlib>

namespace psc_tool {

volatile std::sig_atomic_t interrupted = 0;
volatile std::sig_atomic_t interrupt_signal = SIGINT;
char temporary_output_path[4096] = "";
std::string current_phase = "startup";

void test_signal_at_phase_start(const std::string& phase)
{
  static const char* const hook = std::getenv("PSC_TOOL_TEST_SIGNAL");
  static int seen = 0;
  if(!hook || seen < 0)
    return;
  const std::string h = hook;
  const std::size_t at = h.find('@'), hash = h.find('#');
  if(at == std::string::npos)
    return;
  const std::string name = h.substr(at + 1, hash == std::string::npos ? std::string::npos : hash - at - 1);
  const int nth = hash == std::string::npos ? 1 : std::atoi(h.c_str() + hash + 1);
  const std::size_t star = name.find('*');
  const std::string head = name.substr(0, star), tail = star == std::string::npos ? "" : name.substr(star + 1);
  if(phase.compare(0, head.size(), head) != 0 ||
     (star != std::string::npos &&
      (phase.size() < head.size() + tail.size() || phase.compare(phase.size() - tail.size(), tail.size(), tail) != 0)))
    return;
  if(++seen < nth)
    return;
  seen = -1;  // once
  const std::string signal = h.substr(0, at);
  std::raise(signal == "TERM" ? SIGTERM : signal == "KILL" ? SIGKILL : SIGINT);
}

}  // namespace psc_tool

extern "C" void on_interrupt(int signal)
{
  using namespace psc_tool;
  if(interrupted)
  {
    if(temporary_output_path[0] != '\0')
      ::unlink(temporary_output_path);
    ::_exit(128 + signal);
  }
  interrupt_signal = signal;
  interrupted = 1;
}
