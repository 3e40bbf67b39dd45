// Graphviz DOT for ltl/automaton_io.h: the writer to_dot (accepting states doubled circles, an
// arrow from an invisible start node to each initial state, edge labels spelled with the
// propositions' names). There is no DOT reader.
#include <cstdint>
#include <string>

#include "ltl/automaton_io.h"
#include "ltl/automaton_io_internal.h"

namespace rearm::ltl {
namespace {

using io_detail::kOneAction;
using io_detail::kOneActionNote;
using io_detail::label_expr;
using io_detail::quoted;
using io_detail::spell;
using io_detail::Spelling;
using io_detail::state_name;

constexpr Spelling kDotSpelling{"true", "false", " & ", " | ", false};

template <class Alphabet>
std::string write_dot(const Automaton<Alphabet>& a) {
  std::string out = "digraph nba {\n";
  if constexpr (kOneAction<Alphabet>) out += std::string("  /* ") + kOneActionNote + " */\n";
  out += "  rankdir=LR;\n  node [shape=circle];\n";
  out += "  start [label=\"\", shape=point, style=invis, width=0];\n";
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    const std::string sname = state_name(a, q);
    out +=
        "  " + std::to_string(q) + " [label=" + quoted(sname.empty() ? std::to_string(q) : sname);
    if (a.accepting[q]) out += ", shape=doublecircle";
    out += "];\n";
  }
  for (const std::uint32_t q : a.initial) out += "  start -> " + std::to_string(q) + ";\n";
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    for (const auto& e : a.out[q]) {
      out += "  " + std::to_string(q) + " -> " + std::to_string(e.dst) + " [label=" +
             quoted(spell(label_expr(a.alphabet, e.guard), a.alphabet.aps(), kDotSpelling, true)) +
             "];\n";
    }
  }
  return out + "}\n";
}

}  // namespace

std::string to_dot(const GeneralNba& a) { return write_dot(a); }
std::string to_dot(const ActionNba& a) { return write_dot(a); }

}  // namespace rearm::ltl
