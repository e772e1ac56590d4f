// What the board does with a batch after POSTing it, by the HTTP status
// (negative values are the Arduino HTTPClient's transport errors: no
// connection, timeout, ...). Delivered: release the readings. RetryLater:
// keep them and back off (transport errors, 408 and 429, the server's 5xx, and
// 401/403, since a token can be fixed on the server while the readings wait).
// Discard: the service will never accept this body (any other 4xx, e.g. 400
// or 413), so keeping it would block the queue forever; the readings are
// dropped and counted.
#pragma once

namespace alplan::firmware {

enum class UploadVerdict { Delivered, RetryLater, Discard };

UploadVerdict classify_upload_status(int http_status);

}  // namespace alplan::firmware
