#include <impact_fem/campaign/checksums.h>

#include <openssl/evp.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace impact_fem
{
  namespace checksums
  {
    std::string
    sha256_of_file(const std::string &file_name)
    {
      std::ifstream in(file_name, std::ios::binary);
      if (!in)
        throw std::runtime_error("cannot read " + file_name);
      const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(
        EVP_MD_CTX_new(), &EVP_MD_CTX_free);
      if (!context ||
          EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("OpenSSL: SHA-256 not available");
      std::array<char, 1 << 16> buffer;
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          if (in.gcount() > 0)
            EVP_DigestUpdate(context.get(), buffer.data(), in.gcount());
        }
      if (in.bad())
        throw std::runtime_error("error while reading " + file_name);
      std::array<unsigned char, EVP_MAX_MD_SIZE> digest;
      unsigned int                               length = 0;
      EVP_DigestFinal_ex(context.get(), digest.data(), &length);
      static const char hex[] = "0123456789abcdef";
      std::string       result;
      for (unsigned int i = 0; i < length; ++i)
        {
          result += hex[digest[i] >> 4];
          result += hex[digest[i] & 15];
        }
      return result;
    }


    void
    write_manifest(const std::string              &directory,
                   const std::vector<std::string> &files)
    {
      std::ostringstream text;
      for (const auto &name : files)
        text << sha256_of_file(directory + "/" + name) << "  " << name << "\n";
      const std::string manifest = directory + "/" + manifest_name;
      const std::string temporary =
        manifest + ".tmp" + std::to_string(::getpid());
      {
        std::ofstream out(temporary);
        out << text.str();
        out.close();
        if (!out)
          throw std::runtime_error("cannot write " + temporary);
      }
      std::filesystem::rename(temporary, manifest);
    }


    std::string
    check_manifest(const std::string        &directory,
                   std::vector<std::string> &listed)
    {
      listed.clear();
      std::ifstream in(directory + "/" + manifest_name);
      if (!in)
        return std::string(manifest_name) + ": missing";
      std::string line;
      while (std::getline(in, line))
        {
          // sha256sum's text mode: digest, two spaces (or " *"), name.
          if (line.size() < 67 ||
              (line.compare(64, 2, "  ") != 0 &&
               line.compare(64, 2, " *") != 0) ||
              line.find_first_not_of("0123456789abcdef") < 64)
            return std::string(manifest_name) + ": malformed line <" + line +
                   ">";
          listed.push_back(line.substr(66));
        }
      if (listed.empty())
        return std::string(manifest_name) + ": empty";
      in.clear();
      in.seekg(0);
      while (std::getline(in, line))
        {
          const std::string name = line.substr(66);
          const std::string file = directory + "/" + name;
          if (!std::filesystem::is_regular_file(file))
            return name + ": missing";
          try
            {
              if (sha256_of_file(file) != line.substr(0, 64))
                return name + ": checksum differs";
            }
          catch (const std::exception &)
            {
              return name + ": unreadable";
            }
        }
      return std::string();
    }
  } // namespace checksums
} // namespace impact_fem
