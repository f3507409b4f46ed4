// Session recovery: while the editor runs, the document is saved every minute to a
// recovery file in the editor's config folder (atomically: core/atomic_file.hpp). A clean
// exit removes it and marks the session "clean"; so when the next start finds the recovery file
// and a session marker that does not say "clean", the last session crashed (or was killed) and
// the editor offers to restore it. An flock on "session.lock" makes a second editor running at
// the same time leave the first one's files alone (it does not autosave). The file is written off
// the UI thread: its fsync held a frame for 100-150 ms when the disk was busy.
#pragma once

#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <string_view>

#include "app/editor/document/document.hpp"

namespace fraktal::editor {

inline constexpr double kAutosaveIntervalSeconds = 60.0;

struct RecoveryPaths {
    std::filesystem::path recovery;  // the autosaved preset (with its "editor" section)
    std::filesystem::path marker;    // {"state": "running" | "clean"} of the last session
    std::filesystem::path lock;      // held with flock while a session runs
};
RecoveryPaths recoveryPaths(const std::filesystem::path& configFolder);

// What a start found of the previous session.
enum class PreviousSession { None, Clean, Unclean };
PreviousSession parseSessionMarker(const std::string& text);  // anything unreadable is Unclean

// Offer a restore only when there is something to restore and the last session did not end well.
bool shouldOfferRecovery(PreviousSession previous, bool recoveryFileExists);

enum class AutosaveAction { Nothing, Write, Remove };
// Once a minute, and only when the document has unsaved changes that are not in the recovery
// file yet; a document without unsaved changes needs no recovery file.
AutosaveAction autosaveDecision(double now, double lastWrite, bool dirty, const std::string& fingerprint,
                                const std::string& recoveryFingerprint);

// The recovery file keeps the document (a 3D preset with its "editor" section, or a 2D preset)
// and the file it belongs to ("" for an unsaved one) in a "recovery" section.
std::string recoveryText(const Document& doc, const std::filesystem::path& originalFile);
// The document and its original file back from a recovery file's text. Throws PresetError
// naming `file` when the text is not a recovery file.
Document documentFromRecovery(std::string_view text, const std::string& file, std::filesystem::path& originalFile);

struct RecoveryOffer {
    Document doc;
    std::filesystem::path originalFile;
};

struct AutosaveState {
    RecoveryPaths paths;
    bool enabled = false;  // this session holds the lock and owns the recovery file
    int lockFd = -1;
    double lastWrite = 0.0;
    std::string recoveryFingerprint;     // fingerprint of what the recovery file holds ("" none)
    std::optional<RecoveryOffer> offer;  // found at start: the restore prompt shows it
    std::string error;                   // the last failure, for the status line
    std::future<std::string> writing;    // the recovery file being written: its failure ("" none)
};

// Takes the lock, reads what the previous session left, and marks this one "running". Returns
// false (autosave disabled, s.error says why) when another editor holds the lock or the folder is
// not writable.
bool beginSession(AutosaveState& s, const std::filesystem::path& configFolder, double now);
// Writes (on a thread of its own, one write at a time) or removes the recovery file per
// autosaveDecision; never throws (s.error, once the write has ended).
void autosaveTick(AutosaveState& s, const Document& doc, const std::filesystem::path& originalFile, bool dirty,
                  double now);
// The user answered the restore prompt. Restoring keeps the recovery file (the restored document
// has unsaved changes until the user saves it); declining deletes it.
std::optional<RecoveryOffer> answerRecovery(AutosaveState& s, bool restore);
// Waits for a write in flight and takes its failure into s.error.
void finishAutosave(AutosaveState& s);
// Clean exit: removes the recovery file, marks the session "clean" and releases the lock.
void endSession(AutosaveState& s);
// What a crash does: the lock goes, the files stay (for tests of the crash path; a write in flight
// ends first).
void abandonSession(AutosaveState& s);

}  // namespace fraktal::editor
