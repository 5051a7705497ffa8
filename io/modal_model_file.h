// io/modal_model_file.h — a body's modal model cached on disk (issue 22; docs/solids.md, Cache):
// one file per key in a cache folder, `KEY.modes`, named by a 64-bit FNV-1a hash of the mesh file's
// bytes and every setting that shapes the modes. Binary, this machine's byte order (a cache is
// not an exchange format); a file that does not decode as the key's is ignored and made again.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "acoustics/modal/modal_analysis.h"

namespace fluidsound::io {

/// @brief The cache key of a body: FNV-1a 64 of the mesh file's bytes, continued over `settings`
///        (every value that shapes the modes as text: scale, material, resolution, mode count,
///        highest frequency, clamped face) and the format's name.
/// @throws InputError if the mesh cannot be read
std::uint64_t modalCacheKey(const std::filesystem::path& mesh, std::string_view settings);

/// @brief The cache key of a body given by numbers alone (a box or a sphere): FNV-1a 64 of
///        `settings` (its shape's sizes and every setting that shapes the modes) and the format's name.
std::uint64_t modalCacheKey(std::string_view settings);

/// The cache file of `key` in `folder`: FOLDER/KEY.modes (16 hex digits).
std::filesystem::path modalCacheFile(const std::filesystem::path& folder, std::uint64_t key);

/// `model` as the bytes of a cache file for `key`.
std::string encodeModalModel(const acoustics::ModalModel& model, std::uint64_t key);

/// @brief The model in `bytes`, or nothing if they are not a whole cache file of `key`.
std::optional<acoustics::ModalModel> decodeModalModel(std::string_view bytes, std::uint64_t key);

/// @brief The cached model of `key` in `folder`, or nothing (no file, not a regular file, another
///        key's or a damaged one).
std::optional<acoustics::ModalModel> readCachedModes(const std::filesystem::path& folder, std::uint64_t key);

/// @brief Writes the model to its cache file (temporary + rename), creating `folder` if needed.
/// @return why it was not written ("… is not a regular file: left alone"), or nothing when it was:
///         a cache that cannot be written is not an error of the command.
std::optional<std::string> writeCachedModes(const std::filesystem::path& folder, std::uint64_t key,
                                            const acoustics::ModalModel& model);

}  // namespace fluidsound::io
