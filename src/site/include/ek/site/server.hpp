#pragma once
/// \file
/// A static file server for a site held in memory (`knots serve`): HTTP/1.1
/// on the loopback interface (127.0.0.1) only, GET and HEAD only, one
/// request per connection. It answers only the site's own files: a target
/// is percent-decoded, its query and fragment dropped, "/" and folders map to
/// index.html; a target with a ".." or "." segment, a backslash or a NUL is
/// refused (403), anything else not in the site is 404. It reads no file
/// from disk and runs no command.
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "ek/site/site.hpp"

namespace ek {

/// The port, the workers and the limits of SiteServer.
struct ServeOptions {
  int port = 8000;            ///< [1] TCP port on 127.0.0.1; 0: any free port
  int workers = 8;            ///< [1] connections served at once
  int timeout_seconds = 10;   ///< [s] a client must send its request (and take the answer) within this
  size_t max_request = 16384; ///< [bytes] longest request head accepted (431 beyond)
};

/// The answer to one request.
struct HttpResponse {
  int status = 200;          ///< HTTP status code: 200, 403, 404, 405, ...
  std::string reason;        ///< "OK", "Not Found", ...
  std::string content_type;  ///< Content-Type of the body (content_type())
  std::string body;          ///< the file, or a one-line text for errors
};

/// The answer of the server to `method` `target` (the request line's parts).
HttpResponse respond(const SiteFiles& files, const std::string& method, const std::string& target);

/// The response head and body as sent (the body omitted for HEAD).
std::string http_message(const HttpResponse& response, bool head_only);

/// Serves a site's files (held in memory) on 127.0.0.1 with a few worker
/// threads (see the file's description).
class SiteServer {
 public:
  /// Binds 127.0.0.1:port and listens; InputError when the port is taken or
  /// not allowed.
  SiteServer(SiteFiles files, const ServeOptions& options);
  ~SiteServer();  ///< Stops the workers and closes the sockets.
  /// Not copyable: one server owns its socket and threads.
  SiteServer(const SiteServer&) = delete;
  SiteServer& operator=(const SiteServer&) = delete;  ///< Not copyable.

  /// The bound port (the chosen one for port 0).
  int port() const { return port_; }
  /// Serves until `stop` becomes true (checked every 200 ms), then returns.
  void serve(const std::atomic<bool>& stop);

 private:
  void worker();
  void handle(int fd);

  SiteFiles files_;
  ServeOptions options_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<int> queue_;
  bool closing_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace ek
