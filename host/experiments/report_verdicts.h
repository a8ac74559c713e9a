// report_verdicts.h -- the answer of a results document (report.h): the
// verdicts at equal time per method and baseline, the pairs that were not at
// equal time with their reasons, and one sentence that says the answer.
#pragma once

#include "experiments/report_table.h"
#include "experiments/results.h"

#include <map>
#include <string>

namespace lb::experiments {

struct VerdictReport {
    // Methods as rows, one column group per baseline: wins / ties / losses in
    // NMSE and in FLIP over the pairs at equal time, the off-time pairs, the
    // geometric mean of NMSE method / NMSE MC over the pairs at equal time.
    report::Table verdicts;
    // Per method and baseline with an off-time pair or an NMSE loss: the
    // off-time pairs by reason (results::offTimeClass), the scenes lost.
    report::Table details;
    // One sentence, Markdown: the best method against the strongest baseline
    // at equal time on this device (strongestBaseline), or why there is none.
    std::string headline;
};

// `viewerIndex`: scene label -> its index in the report's picture viewer
// (links to the lost scenes), may be empty.
VerdictReport verdictReport(const results::Results& doc, const std::map<std::string, size_t>& viewerIndex);

// Counts of one method against one baseline.
struct VerdictCount {
    int win = 0, tie = 0, loss = 0, undefined = 0;
    int onTime() const { return win + tie + loss + undefined; }
};
struct PairTally {
    VerdictCount nmse, flip;
    int offTime = 0;
    std::map<std::string, int> offTimeBy;  // results::offTimeClass -> pairs
    double logSum = 0;  // of NMSE method / NMSE MC over the pairs at equal time with both finite
    int logs = 0;
    std::vector<const results::Record*> lost;  // partners of NMSE losses
    double ratio() const { return logs ? std::exp(logSum / logs) : NAN; }
};
// The tallies by method (as the experiment wrote it) and baseline label, in
// the order first met (methods) and the order of the run's baselines
// (context "baselines", then as first met).
struct Tallies {
    std::vector<std::string> methods, baselines;
    std::map<std::string, std::map<std::string, PairTally>> by;  // method -> baseline -> tally
};
Tallies tallyPairs(const results::Results& doc);

// The strongest baseline: of the baselines with at least half as many pairs
// at equal time as the one with the most, the one with the highest
// geometric mean of NMSE method / NMSE MC over its pairs at equal time
// (the methods fare worst against it); "" when no pair is at equal time.
std::string strongestBaseline(const Tallies& t);

}  // namespace lb::experiments
