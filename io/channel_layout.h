// io/channel_layout.h — what a written WAV or FLAC says about its channels: listeners are points
// in a scene, not loudspeakers, so a file with 3 or more channels carries no speaker positions
// (a player would otherwise read 6 listeners as 5.1 surround), and a WAV names each channel
// after its listener in an iXML chunk (docs/audio.md, "Channels").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fluidsound::io {

/// Files with at least this many channels are marked "no speaker positions"; mono and stereo
/// keep the plain meaning every player gives them (one listener; a left/right pair).
constexpr std::size_t kFirstUnpositionedChannelCount = 3;

/// @brief The iXML document (iXML specification 2.10, TRACK_LIST) naming channel k+1 `names[k]`,
///        for a WAV file's `iXML` chunk; names are XML-escaped.
std::string ixmlTrackList(const std::vector<std::string>& names);

/// @brief Sets the speaker mask (dwChannelMask) of an encoded WAVE_FORMAT_EXTENSIBLE file in
///        memory to 0, "no speaker positions": libsndfile writes the usual surround masks for 4,
///        6 and 8 channels and offers no way to ask for none. `name` is the output's, for errors.
/// @throws OutputError if the bytes are not a WAVE_FORMAT_EXTENSIBLE file
void clearWaveSpeakerMask(std::string& wav, const std::filesystem::path& name);

/// @brief Gives an encoded FLAC stream in memory the Vorbis comment
///        WAVEFORMATEXTENSIBLE_CHANNEL_MASK=0x0 (no speaker positions; the FLAC format's way to
///        override its default layouts for 3–8 channels), keeping any other comments; the audio
///        frames are kept byte for byte. `name` is the output's, for errors.
/// @throws OutputError if `flac` is not a FLAC stream
void clearFlacSpeakerMask(std::string& flac, const std::filesystem::path& name);

}  // namespace fluidsound::io
