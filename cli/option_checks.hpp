// Checks every command applies to its arguments before any work starts, so a mistake gets one line
// naming the argument, what was found and what was expected (never a C++ exception's text):
//   - numbers are read strictly: an unsigned option refuses "-1" (CLI11 would wrap it to 2^64-1),
//     values beyond the type are refused rather than clamped, and text after the digits is refused;
//   - input files must exist, be regular files (or directories where one is expected) and be readable;
//   - an option's value never starts with "--": `config --check --stream x` left --check without
//     its file, and CLI11 would take the next word whatever it is.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// An input file: exists, is not a directory, can be opened for reading.
const CLI::Validator& inputFile();
// An input directory: exists and is a directory.
const CLI::Validator& inputDirectory();
// A transform for an input option: "-" becomes the path of standard input's bytes
// (streams/disc/standard_input.hpp: read on first use, once per process), any other value is left as
// it is. Register it before the option's check(inputFile()).
const CLI::Validator& stdinAsFile();
// A count, seed or size that cannot be negative (text of digits only, fits in 64 bits).
const CLI::Validator& nonNegativeInteger();

// True when `opt` has a check of that name ("input file", "input directory", CLI11's "DIR").
bool hasValidator(CLI::Option& opt, const std::string& name);

// Adds the strict number checks to every option of `app` and its subcommands whose type is an
// integer or a floating-point number (CLI11's INT, UINT and FLOAT), and gives each option a plain
// type name in --help (CLI11 appends validator names: "INT:NONNEGATIVE").
void checkNumbersStrictly(CLI::App& app);

// Makes every option of `app` and its subcommands that takes a value refuse a value starting with
// "--" (the user left the value out and the next option was taken in its place) and an empty value
// (`--out ''`), before any other check of the value and so before any work: "--check: expects a
// file, got the option '--stream'", "--out: is empty; expected the name of what to write". Call it after
// checkNumbersStrictly, which sets the type names it reads.
void refuseOptionsAsValues(CLI::App& app);

}  // namespace vbim::cli
