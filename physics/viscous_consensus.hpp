#pragma once
// The consensus of published 2D values for flow past a (spinning) cylinder: one value per scene and
// quantity where independent studies agree, with their sources and the tolerance the viscous model is held
// to (tests/validation/test_ns_consensus.cpp). Tabulated values unless `sources` says "digitised" (read
// off a figure, with the stated uncertainty). C_L as a magnitude: magnus's sign is C_L < 0 for α > 0.
#include <cstring>
#include <stdexcept>
#include <string>

namespace magnus {

/// One published value: scene (Re = U·2a/ν, α = aω/U, the outer radius when it matters), quantity, value.
struct ConsensusValue {
  const char* id;            ///< short key, e.g. "re20_cd"
  double reynolds;           ///< Re = U·2a/ν
  double alpha;              ///< spin ratio aω/U
  double outer_over_a;       ///< R/a the value belongs to (0: a domain-independent value)
  const char* quantity;      ///< "C_D", "|C_L|", "St", "C_L amplitude", "L_w/D", "theta_s (deg)", …
  double value;              ///< the consensus value (units of the quantity: 1, D or degrees)
  const char* sources;       ///< who published it, and how (table, digitised ±)
  double tolerance;          ///< relative: |ours − value| ≤ tolerance·|value|
};

// clang-format off
/// The table. L_w: the recirculation length behind the rear surface, over D. θ_s: the separation angle
/// measured from the rear stagnation point.
inline constexpr ConsensusValue kViscousConsensus[] = {
  {"re20_cd",     20, 0,   0,  "C_D",    2.000, "Fornberg 1980", 0.01},
  {"re20_lw",     20, 0,   0,  "L_w/D",  0.915, "Fornberg 0.91; Dennis & Chang 0.94; Giannetti & Luchini 0.93", 0.02},
  {"re40_cd_60",  40, 0,  60,  "C_D",    1.4906, "Gautier et al. 2013 (R = 30 D)", 0.002},
  {"re40_cd_80",  40, 0,  80,  "C_D",    1.4931, "Gautier et al. 2013 (R = 40 D)", 0.002},
  {"re40_cd_100", 40, 0, 100,  "C_D",    1.4943, "Gautier et al. 2013 (R = 50 D)", 0.002},
  {"re40_lw",     40, 0,   0,  "L_w/D",  2.236, "Gautier et al. 2013; Fornberg 1980 2.24", 0.01},
  {"re40_sep",    40, 0,   0,  "theta_s (deg)", 53.7, "53.5-53.9: Fornberg; Dennis & Chang 53.8", 0.01},
  {"re100_a0_cd", 100, 0,  0,  "C_D",    1.320, "Qu et al. 2013; Posdziech & Grundmann 2007", 0.01},
  {"re100_a0_st", 100, 0,  0,  "St",     0.1644, "Qu et al. 2013; Posdziech & Grundmann 2007", 0.005},
  {"re100_a1_cl", 100, 1,  0,  "|C_L|",  2.495, "Kang, Choi & Lee 1999 2.488; Stojkovic et al. 2002 2.504", 0.005},
  {"re100_a1_cd", 100, 1,  0,  "C_D",    1.093, "Kang et al. 1999 1.104 at 50 D, -0.55% to 100 D, -0.43% to 301^2; Stojkovic et al. 2002 1.108", 0.01},
  {"re100_a1_st", 100, 1,  0,  "St",     0.1652, "Kang et al. 1999 0.1650-0.1656; Stojkovic et al. 2002 0.1658", 0.005},
  {"re100_a1_amp", 100, 1, 0,  "C_L amplitude", 0.357, "Kang et al. 1999 0.358-0.363; Stojkovic et al. 2002 0.362", 0.025},
  {"re100_a15_cd", 100, 1.5, 0, "C_D",   0.816, "Stojkovic et al. 2002 0.818 (table); Kang et al. 1999 0.815 (digitised ±0.01)", 0.025},
  {"re100_a2_cl", 100, 2,  0,  "|C_L|",  5.48, "Stojkovic et al. 2002 (table)", 0.01},
  {"re100_a2_cd", 100, 2,  0,  "C_D",    0.465, "Stojkovic et al. 2002 0.46 (two digits); Kang et al. 1999 0.471 (digitised)", 0.03},
  // α 4–6: digitised ±0.15 (0.9% at α 4, 0.44% at α 6) plus ~0.5% for the source's own grid; α 5: the
  // two studies' spread (C_D 0.32 against 0.329) and St's two digits (±0.0005).
  {"re100_a4_cl", 100, 4,  0,  "|C_L|",  17.00, "Stojkovic et al. 2002 Fig. 13, digitised ±0.15", 0.015},
  {"re100_a6_cl", 100, 6,  0,  "|C_L|",  34.38, "Stojkovic et al. 2002 Fig. 13, digitised ±0.15", 0.01},
  {"re100_a5_cl", 100, 5,  0,  "|C_L|",  26.5, "Munir et al. 2021 26.5; Bourguet 2020 26.6; Stojkovic Fig. 13 26.53", 0.015},
  {"re100_a5_cd", 100, 5,  0,  "C_D",    0.329, "Munir et al. 2021 0.329; Bourguet 2020 0.32", 0.05},
  {"re100_a5_st", 100, 5,  0,  "St",     0.022, "Munir et al. 2021; Bourguet 2020 (the one-sided second mode)", 0.05},
};
// clang-format on

/// The table's entry `id`. Throws std::invalid_argument naming an id the table does not hold.
inline const ConsensusValue& consensus(const char* id) {
  for (const ConsensusValue& v : kViscousConsensus)
    if (std::strcmp(v.id, id) == 0) return v;
  throw std::invalid_argument(std::string("viscous consensus: no entry '") + id + "'");
}

}  // namespace magnus
