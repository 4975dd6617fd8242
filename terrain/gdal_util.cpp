#include "terrain/gdal_util.h"

#include <cpl_error.h>

#include <algorithm>
#include <mutex>

namespace skylit::terrain::detail {

void ensure_gdal_registered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

GdalErrorCapture::GdalErrorCapture() { CPLPushErrorHandlerEx(&GdalErrorCapture::handler, this); }

GdalErrorCapture::~GdalErrorCapture() { CPLPopErrorHandler(); }

void CPL_STDCALL GdalErrorCapture::handler(CPLErr cls, CPLErrorNum, const char* msg) {
  auto* self = static_cast<GdalErrorCapture*>(CPLGetErrorHandlerUserData());
  std::string line = msg ? msg : "";
  std::replace(line.begin(), line.end(), '\n', ' ');
  if (cls == CE_Failure || cls == CE_Fatal)
    self->failures_.push_back(std::move(line));
  else if (cls == CE_Warning)
    self->warnings_.push_back(std::move(line));
}

std::string GdalErrorCapture::failure(const std::string& fallback) const {
  return failures_.empty() ? fallback : failures_.back();
}

}  // namespace skylit::terrain::detail
