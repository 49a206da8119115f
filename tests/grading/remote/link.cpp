// The pipe pair's framing (link.hpp): a header of two 32-bit words, then the body.
#include "link.hpp"

#include <unistd.h>

#include <cerrno>
#include <exception>
#include <stdexcept>

namespace kit::remote {
namespace {

bool write_all(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= std::size_t(n);
  }
  return true;
}

bool read_all(int fd, void* data, std::size_t size) {
  auto* bytes = static_cast<unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= std::size_t(n);
  }
  return true;
}

}  // namespace

void Link::send(Kind kind, const std::vector<unsigned char>& body) {
  if (gone_) throw PeerGone("the other process has gone");
  if (body.size() > kMaxMessage)
    throw ProtocolError("a message over " + std::to_string(kMaxMessage) + " bytes");
  const std::uint32_t header[2] = {std::uint32_t(kind), std::uint32_t(body.size())};
  if (!write_all(out_, header, sizeof header) || !write_all(out_, body.data(), body.size())) {
    gone_ = true;
    throw PeerGone("the other process has gone (its pipe is closed)");
  }
}

Message Link::receive() {
  if (gone_) throw PeerGone("the other process has gone");
  std::uint32_t header[2];
  if (!read_all(in_, header, sizeof header)) {
    gone_ = true;
    throw PeerGone("the other process has gone: it exited, crashed or was stopped mid-call");
  }
  if (header[0] < 1 || header[0] > 6 || header[1] > kMaxMessage) {
    gone_ = true;  // out of step: nothing after this can be trusted to be a header
    throw ProtocolError("a message with no valid header");
  }
  Message m{Kind(header[0]), std::vector<unsigned char>(header[1])};
  if (!read_all(in_, m.body.data(), m.body.size())) {
    gone_ = true;
    throw PeerGone("the other process has gone mid-message");
  }
  return m;
}

void rethrow(Reader& r) {
  const auto failure = get<Failure>(r);
  const auto text = get<std::string>(r).substr(0, 2000);
  switch (failure) {
    case Failure::invalid_argument:
      throw std::invalid_argument(text);
    case Failure::domain_error:
      throw std::domain_error(text);
    case Failure::out_of_range:
      throw std::out_of_range(text);
    case Failure::logic_error:
      throw std::logic_error(text);
    case Failure::runtime_error:
      throw std::runtime_error(text);
    default:
      throw std::runtime_error("an exception of an unknown type: " + text);
  }
}

std::vector<unsigned char> describe_current_exception() {
  Writer w;
  auto send = [&](Failure failure, const char* text) {
    put(w, failure);
    put(w, std::string(text));
  };
  try {
    throw;
  } catch (const std::invalid_argument& e) {
    send(Failure::invalid_argument, e.what());
  } catch (const std::domain_error& e) {
    send(Failure::domain_error, e.what());
  } catch (const std::out_of_range& e) {
    send(Failure::out_of_range, e.what());
  } catch (const std::logic_error& e) {
    send(Failure::logic_error, e.what());
  } catch (const std::runtime_error& e) {
    send(Failure::runtime_error, e.what());
  } catch (const std::exception& e) {
    send(Failure::other, e.what());
  } catch (...) {
    send(Failure::other, "not a std::exception");
  }
  return std::move(w.bytes());
}

}  // namespace kit::remote
