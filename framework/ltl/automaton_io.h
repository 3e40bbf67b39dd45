// Automaton input and output: HOA (Hanoi Omega-Automata v1, as Spot and Owl read and write
// it), spin never claims, Graphviz DOT. Readers produce a GeneralNba (BDD guards); they
// accept what Spot, ltl2ba and `spin -f` print (quirks in docs/symbolic.md) and throw
// rearm::Error with the line and the reason for anything else.
#pragma once

#include <string>
#include <string_view>

#include "ltl/automaton.h"

namespace rearm::ltl {

// HOA v1, state-based Büchi ("Acceptance: 1 Inf(0)", "acc-name: Buchi"), explicit labels.
// For an ActionNba the labels are exact on symbols with at most one true proposition, and
// the header carries a comment saying so.
std::string to_hoa(const GeneralNba& a, const std::string& name = "");
std::string to_hoa(const ActionNba& a, const std::string& name = "");

// Spin never claim (states T<k>_init / accept_..., "if :: (guard) -> goto s fi;").
std::string to_never_claim(const GeneralNba& a);
std::string to_never_claim(const ActionNba& a);

// Graphviz DOT (accepting states doubled circles, initial arrow, labels as in HOA with
// proposition names).
std::string to_dot(const GeneralNba& a);
std::string to_dot(const ActionNba& a);

// Readers. Propositions are mapped by name into `alphabet` (new names are added), so an
// automaton can be read into the same BDD manager and proposition order as another one.
// read_hoa accepts state-based and transition-based Büchi acceptance (Inf(0), "t" = all
// accepting; transition marks are moved onto states by splitting), explicit labels, AP
// aliases (@name), and multiple initial states; anything else is a clear error.
GeneralNba read_hoa(std::string_view text, GeneralAlphabet alphabet = GeneralAlphabet());
GeneralNba read_never_claim(std::string_view text, GeneralAlphabet alphabet = GeneralAlphabet());

}  // namespace rearm::ltl
