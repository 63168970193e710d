#include "k40t_driver/psdk/aes.h"

#include <openssl/crypto.h>
#include <openssl/err.h>
#include <openssl/evp.h>

#include <limits>
#include <memory>

namespace k40t::psdk {
namespace {

std::string openssl_error(const char* what) {
  const unsigned long code = ERR_get_error();
  char reason[256] = "unknown OpenSSL error";
  if (code != 0) ERR_error_string_n(code, reason, sizeof(reason));
  return std::string("AES-128-ECB ") + what + " failed: " + reason;
}

struct CipherContextDeleter {
  void operator()(EVP_CIPHER_CTX* ctx) const { EVP_CIPHER_CTX_free(ctx); }
};
struct DigestContextDeleter {
  void operator()(EVP_MD_CTX* ctx) const { EVP_MD_CTX_free(ctx); }
};

}  // namespace

Aes128Ecb::~Aes128Ecb() {
  OPENSSL_cleanse(key_.data(), key_.size());
}

Status Aes128Ecb::encrypt(const uint8_t* in, size_t size, uint8_t* out) const {
  return run(true, in, size, out);
}
Status Aes128Ecb::decrypt(const uint8_t* in, size_t size, uint8_t* out) const {
  return run(false, in, size, out);
}

Status Aes128Ecb::run(bool encrypt, const uint8_t* in, size_t size, uint8_t* out) const {
  const char* what = encrypt ? "encryption" : "decryption";
  if (size % kAesBlockSize != 0) {
    return Status::fail(std::string("AES-128-ECB ") + what + " needs whole 16-byte blocks, got " +
                        std::to_string(size) + " bytes");
  }
  if (size == 0) return Status::ok();
  if (size > static_cast<size_t>(std::numeric_limits<int>::max())) {
    return Status::fail(std::string("AES-128-ECB ") + what + ": buffer too large");
  }
  std::unique_ptr<EVP_CIPHER_CTX, CipherContextDeleter> ctx(EVP_CIPHER_CTX_new());
  if (!ctx) return Status::fail(openssl_error(what));
  if (EVP_CipherInit_ex(ctx.get(), EVP_aes_128_ecb(), nullptr, key_.data(), nullptr,
                        encrypt ? 1 : 0) != 1) {
    return Status::fail(openssl_error(what));
  }
  // The frame pads DATA itself (zero fill, count in the header): no PKCS#7 block on top.
  EVP_CIPHER_CTX_set_padding(ctx.get(), 0);
  int written = 0;
  if (EVP_CipherUpdate(ctx.get(), out, &written, in, static_cast<int>(size)) != 1) {
    return Status::fail(openssl_error(what));
  }
  int final_written = 0;
  if (EVP_CipherFinal_ex(ctx.get(), out + written, &final_written) != 1)
    return Status::fail(openssl_error(what));
  if (static_cast<size_t>(written + final_written) != size) {
    return Status::fail(std::string("AES-128-ECB ") + what + " produced " +
                        std::to_string(written + final_written) + " bytes for " +
                        std::to_string(size));
  }
  return Status::ok();
}

Md5Digest md5(const uint8_t* first, size_t first_size, const uint8_t* second, size_t second_size) {
  Md5Digest digest{};
  std::unique_ptr<EVP_MD_CTX, DigestContextDeleter> ctx(EVP_MD_CTX_new());
  unsigned int size = 0;
  // EVP MD5 cannot fail for in-memory input short of allocation failure; then the digest stays
  // zero, which no verifier accepts.
  if (ctx && EVP_DigestInit_ex(ctx.get(), EVP_md5(), nullptr) == 1 &&
      EVP_DigestUpdate(ctx.get(), first, first_size) == 1 &&
      (second_size == 0 || EVP_DigestUpdate(ctx.get(), second, second_size) == 1)) {
    EVP_DigestFinal_ex(ctx.get(), digest.data(), &size);
  }
  return digest;
}

AesKey derive_aes_key(const Credentials& c) {
  std::string joined = c.app_name + c.app_id + c.app_key + c.developer_account;
  const Md5Digest digest = md5(reinterpret_cast<const uint8_t*>(joined.data()), joined.size());
  OPENSSL_cleanse(joined.data(), joined.size());
  return digest;
}

}  // namespace k40t::psdk
