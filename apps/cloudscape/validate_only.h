#pragma once
// A validate-only mode for the CLI fuzz harness (fuzz/fuzz_cli.cpp): the whole argument parser
// and every command's checks run in-process, but nothing is rendered or written. Each command
// calls stopIfValidatingOnly() once its arguments and inputs are validated, before any costly
// work or output; in the tool itself the mode is never on and the call does nothing.
namespace cloudscape::cli {

// Thrown by stopIfValidatingOnly() in validate-only mode. Deliberately not a std::exception, so
// main's handlers (which turn exceptions into one-line errors) let it through to the harness.
struct ValidationComplete {};

void setValidateOnly(bool on);
void stopIfValidatingOnly();

} // namespace cloudscape::cli
