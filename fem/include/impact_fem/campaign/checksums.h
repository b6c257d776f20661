#ifndef IMPACT_FEM_CAMPAIGN_CHECKSUMS_H
#define IMPACT_FEM_CAMPAIGN_CHECKSUMS_H

#include <string>
#include <vector>

namespace impact_fem
{
  /**
   * The SHA-256 checksums of a campaign run's result files, kept in the
   * run's directory as `checksums.sha256` in the format of coreutils'
   * sha256sum ("<64 hex digits>  <file name>" per line), so that
   * `sha256sum -c checksums.sha256` checks a run by hand as well. Written
   * after the files are final; a run whose files do not match is damaged.
   * Digests by OpenSSL's libcrypto (EVP interface).
   */
  namespace checksums
  {
    /// The name of the manifest in a run directory.
    inline constexpr const char *manifest_name = "checksums.sha256";

    /// SHA-256 of the file's bytes, 64 lower-case hex digits; throws if
    /// the file cannot be read.
    std::string
    sha256_of_file(const std::string &file_name);

    /// Writes the manifest of @p files (names relative to @p directory),
    /// atomically (temporary file renamed).
    void
    write_manifest(const std::string              &directory,
                   const std::vector<std::string> &files);

    /**
     * Checks every file of the manifest in @p directory. Returns an empty
     * string if all are present and match, else the first problem
     * ("history.h5: checksum differs", "summary.json: missing",
     * "checksums.sha256: missing", ...). @p listed receives the file names
     * of the manifest.
     */
    std::string
    check_manifest(const std::string        &directory,
                   std::vector<std::string> &listed);
  } // namespace checksums
} // namespace impact_fem

#endif
