#pragma once
// A journal's records rewritten in their first layout (magic "RUN1", one
// slot for a knot's Lk or a link's closest approach, a link's energy total
// without contact), as journals begun before the second layout hold them:
// the tests of reading and resuming such journals.
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace ek::testing_journal {

/// `bytes` (a journal whose records follow a header of `head_size` bytes)
/// with every record in the first layout. For a link (`link` true) the slot
/// takes min_distance, energy.total loses the contact part and contacts
/// are 0 (the first layout's link runs did not count them); for a knot the
/// slot keeps Lk.
inline std::string to_first_layout(const std::string& bytes, size_t head_size, bool link) {
  std::string out = bytes.substr(0, head_size);
  for (size_t pos = head_size; pos + 12 <= bytes.size();) {
    std::uint32_t len;
    std::memcpy(&len, bytes.data() + pos + 4, 4);
    std::string p = bytes.substr(pos + 8, len);
    size_t at = 4 + 8;  // sample, seed
    const auto skip_string = [&] {
      std::uint32_t n;
      std::memcpy(&n, p.data() + at, 4);
      at += 4 + n;
    };
    skip_string();                     // status
    const size_t contacts = at + 4 + 4 + 8 + 8 + 8;
    at += 4 + 4 + 8 + 8 + 8 + 4 + 4;   // equilibrium .. topology flag
    skip_string();                     // message
    const size_t total = at, contact = at + 4 * 8, link_slot = at + 7 * 8, min_distance = at + 8 * 8;
    if (link) {
      double e, c;
      std::memcpy(&e, p.data() + total, 8);
      std::memcpy(&c, p.data() + contact, 8);
      e -= c;
      std::memcpy(&p[total], &e, 8);
      std::memcpy(&p[link_slot], p.data() + min_distance, 8);
      const std::int32_t none = 0;
      std::memcpy(&p[contacts], &none, 4);
    }
    p.erase(min_distance, 8);
    const std::uint32_t magic = 0x314E5552, n = static_cast<std::uint32_t>(p.size());
    const auto crc = static_cast<std::uint32_t>(::crc32(0L, reinterpret_cast<const Bytef*>(p.data()), n));
    out.append(reinterpret_cast<const char*>(&magic), 4);
    out.append(reinterpret_cast<const char*>(&n), 4);
    out += p;
    out.append(reinterpret_cast<const char*>(&crc), 4);
    pos += 12 + len;
  }
  return out;
}

}  // namespace ek::testing_journal
