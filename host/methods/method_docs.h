// method_docs.h -- the methods and their parameters as documentation,
// generated from the registry (Family::summary, Family::params): what
// `lumibench methods` prints and docs/methods.md holds (a test regenerates
// it and compares).
#pragma once

#include <string>

namespace lb::methods {

// One line per family: name, the scenes it renders, its summary.
std::string methodsText();

// docs/methods.md: per scene kind a table of the methods, then per family a
// table of its parameters (name, allowed values, default, tunable, meaning).
std::string methodsMarkdown();

}  // namespace lb::methods
