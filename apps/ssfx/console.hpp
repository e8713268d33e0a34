// The tool's output conventions: results on stdout, diagnostics and progress on stderr,
// errors always. -q/--quiet silences everything but errors and the outputs asked for on
// stdout (-o -, --json -). Progress is a status line redrawn in place, drawn only when stderr
// is a terminal (or with --progress); elsewhere (a log, a pipe) each step is one line.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <string_view>

#include "ssfx/core/progress.hpp"

namespace ssfx::cli {

//! Prints "ssfx: error: MESSAGE" on stderr; returns the exit status of bad input, 2.
int reportError(std::string_view message);
//! At start: a closed standard output (`>&-`) gets a descriptor that refuses writes, so
//! that no file opened later takes descriptor 1 and receives the results.
void guardStdout();
//! At exit: flushes stdout; false when anything written to it was lost (a full disk, a
//! closed or broken stdout), with the reason already reported on stderr.
bool finishStdout();

void setQuiet(bool quiet);
bool quiet();
//! Draws progress lines even when stderr is not a terminal (--progress).
void setForceProgress(bool force);

//! A result on stdout (a table, a summary), unless quiet. This and printNote first end a
//! progress line in progress.
void printResult(std::string_view text);
//! A diagnostic line "PREFIX: TEXT" on stderr, unless quiet.
void printNote(std::string_view prefix, std::string_view text);

//! Writes `text` to `path` atomically, or to stdout when `path` is "-" (--json -, --md -).
void writeOutput(const std::string& path, const std::string& text);
//! Whether one of these output paths is stdout ("-"): the command then prints no table.
//! Throws ssfx::Error when more than one is, or when two name one file (--json F --md F:
//! the second would replace the first).
bool anyStdout(std::initializer_list<std::string_view> paths);

//! Reports to the innermost ProgressLine alive, if any (for code that runs inside a command
//! without a handle to its line).
void reportProgress(const Progress& p);

//! The status line of one command. report() may be called from any thread; the line is
//! redrawn at most ten times a second and ended (with the step's count, rate and time) when
//! the step changes or the line is destroyed.
class ProgressLine {
public:
    //! `logSteps`: off a terminal, still write each step's name as one line (an evaluation's
    //! log); otherwise nothing is written off a terminal.
    explicit ProgressLine(std::string prefix, bool logSteps = false);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void report(const Progress& p);
    //! Ends the line if drawn (before other output, so that it is not written over).
    void end();
    //! A ProgressFn that reports here (the line must outlive it).
    ProgressFn fn();

private:
    using Clock = std::chrono::steady_clock;
    void draw(bool final);  // with mutex_ held

    ProgressLine* outer_ = nullptr;  // the line alive before this one
    std::mutex mutex_;
    std::string prefix_, what_, unit_;
    std::int64_t done_ = 0, total_ = 0;
    Clock::time_point start_, lastDraw_;
    bool live_ = false;  // a terminal (or --progress): redraw in place
    bool logSteps_ = false;
    bool drawn_ = false;    // the current line has been drawn and not yet ended
    bool started_ = false;  // a step has been reported
};

}  // namespace ssfx::cli
