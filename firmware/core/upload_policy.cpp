#include "upload_policy.h"

namespace alplan::firmware {

UploadVerdict classify_upload_status(int http_status) {
  if (http_status >= 200 && http_status < 300) return UploadVerdict::Delivered;
  if (http_status == 401 || http_status == 403 || http_status == 408 || http_status == 429) {
    return UploadVerdict::RetryLater;
  }
  if (http_status >= 400 && http_status < 500) return UploadVerdict::Discard;
  return UploadVerdict::RetryLater;
}

}  // namespace alplan::firmware
