#include "app/editor/document/autosave.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kRecoveryKey = "recovery";

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeMarker(const fs::path& marker, const char* state) {
    writeFileAtomically(marker, json{{"state", state}, {"pid", ::getpid()}}.dump() + "\n");
}

}  // namespace

RecoveryPaths recoveryPaths(const fs::path& configFolder) {
    return {configFolder / "recovery.json", configFolder / "session.json", configFolder / "session.lock"};
}

PreviousSession parseSessionMarker(const std::string& text) {
    if (text.empty()) return PreviousSession::None;
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_object() && j.value("state", json()) == "clean") return PreviousSession::Clean;
    return PreviousSession::Unclean;
}

bool shouldOfferRecovery(PreviousSession previous, bool recoveryFileExists) {
    return recoveryFileExists && previous != PreviousSession::Clean;
}

AutosaveAction autosaveDecision(double now, double lastWrite, bool dirty, const std::string& fingerprint,
                                const std::string& recoveryFingerprint) {
    if (!dirty) return recoveryFingerprint.empty() ? AutosaveAction::Nothing : AutosaveAction::Remove;
    if (now - lastWrite < kAutosaveIntervalSeconds || fingerprint == recoveryFingerprint)
        return AutosaveAction::Nothing;
    return AutosaveAction::Write;
}

std::string recoveryText(const Document& doc, const fs::path& originalFile) {
    json j = json::parse(documentFileText(doc));
    j[kRecoveryKey] = {{"file", originalFile.string()}};
    return j.dump(2) + "\n";
}

Document documentFromRecovery(std::string_view text, const std::string& file, fs::path& originalFile) {
    json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object()) throw PresetError(file, "", "not a recovery file (not a JSON object)");
    const json r = j.value(kRecoveryKey, json());
    originalFile =
        r.is_object() && r.value("file", json()).is_string() ? fs::path(r["file"].get<std::string>()) : fs::path();
    j.erase(kRecoveryKey);
    const std::string preset = j.dump();
    Document d;
    if (isPlanePresetText(preset)) {
        d.plane = parsePlanePreset(preset, file);
    } else {
        d.preset = parsePreset(preset, file);
        loadEditorSection(d);
    }
    return d;
}

bool beginSession(AutosaveState& s, const fs::path& configFolder, double now) {
    s.paths = recoveryPaths(configFolder);
    s.lastWrite = now;
    std::error_code ec;
    fs::create_directories(configFolder, ec);
    s.lockFd = ::open(s.paths.lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (s.lockFd < 0 || ::flock(s.lockFd, LOCK_EX | LOCK_NB) != 0) {
        if (s.lockFd >= 0) ::close(s.lockFd);
        s.lockFd = -1;
        s.error = "another fraktal editor is running: this one does not autosave";
        return false;
    }
    const PreviousSession previous = parseSessionMarker(readText(s.paths.marker));
    if (shouldOfferRecovery(previous, fs::exists(s.paths.recovery, ec))) {
        try {
            RecoveryOffer offer;
            offer.doc = documentFromRecovery(readText(s.paths.recovery), s.paths.recovery.string(), offer.originalFile);
            s.offer = std::move(offer);
        } catch (const std::exception& e) {
            s.error = std::string("the recovery file cannot be read: ") + e.what();
        }
    }
    try {
        writeMarker(s.paths.marker, "running");
    } catch (const std::exception& e) {
        s.error = e.what();
        abandonSession(s);
        return false;
    }
    s.enabled = true;
    return true;
}

void finishAutosave(AutosaveState& s) {
    if (!s.writing.valid()) return;
    const std::string failure = s.writing.get();
    if (failure.empty()) return;
    s.error = failure;
    s.recoveryFingerprint.clear();  // not in the file: the next tick tries again
}

void autosaveTick(AutosaveState& s, const Document& doc, const fs::path& originalFile, bool dirty, double now) {
    // While the restore prompt is open the old recovery file is still the user's to choose.
    if (!s.enabled || s.offer) return;
    if (s.writing.valid()) {
        if (s.writing.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
        finishAutosave(s);
    }
    const std::string print = dirty ? fingerprint(doc) : std::string();
    switch (autosaveDecision(now, s.lastWrite, dirty, print, s.recoveryFingerprint)) {
        case AutosaveAction::Nothing: return;
        case AutosaveAction::Remove: {
            std::error_code ec;
            fs::remove(s.paths.recovery, ec);
            s.recoveryFingerprint.clear();
            return;
        }
        case AutosaveAction::Write:
            s.lastWrite = now;
            try {
                s.writing =
                    std::async(std::launch::async, [file = s.paths.recovery, text = recoveryText(doc, originalFile)] {
                        try {
                            writeFileAtomically(file, text);
                            return std::string();
                        } catch (const std::exception& e) {
                            return std::string("autosave failed: ") + e.what();
                        }
                    });
                s.recoveryFingerprint = print;
            } catch (const std::exception& e) {
                s.error = std::string("autosave failed: ") + e.what();
            }
            return;
    }
}

std::optional<RecoveryOffer> answerRecovery(AutosaveState& s, bool restore) {
    std::optional<RecoveryOffer> offer = std::move(s.offer);
    s.offer.reset();
    if (!offer) return std::nullopt;
    if (restore) {
        s.recoveryFingerprint = fingerprint(offer->doc);
        return offer;
    }
    std::error_code ec;
    if (s.enabled) fs::remove(s.paths.recovery, ec);
    s.recoveryFingerprint.clear();
    return std::nullopt;
}

void endSession(AutosaveState& s) {
    finishAutosave(s);
    if (!s.enabled) return;
    std::error_code ec;
    fs::remove(s.paths.recovery, ec);
    try {
        writeMarker(s.paths.marker, "clean");
    } catch (const std::exception&) {
        // Without the marker the next start sees no recovery file, so it offers nothing either.
    }
    abandonSession(s);
}

void abandonSession(AutosaveState& s) {
    finishAutosave(s);
    if (s.lockFd >= 0) ::close(s.lockFd);  // closing releases the flock
    s.lockFd = -1;
    s.enabled = false;
}

}  // namespace fraktal::editor
