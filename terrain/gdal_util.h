// Internal GDAL helpers shared by the reader and the writer (not a public API).
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

namespace skylit::terrain::detail {

// Registers GDAL's drivers once per process.
void ensure_gdal_registered();

// While alive, GDAL errors and warnings on this thread are collected here instead of
// printed to stderr (messages flattened to one line each).
class GdalErrorCapture {
 public:
  GdalErrorCapture();
  ~GdalErrorCapture();
  GdalErrorCapture(const GdalErrorCapture&) = delete;
  GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;

  bool has_failure() const { return !failures_.empty(); }
  // The last failure message, or `fallback` when GDAL said nothing.
  std::string failure(const std::string& fallback = "unknown GDAL error") const;
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<std::string>& failures() const { return failures_; }

 private:
  static void CPL_STDCALL handler(CPLErr cls, CPLErrorNum num, const char* msg);
  std::vector<std::string> failures_;
  std::vector<std::string> warnings_;
};

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

}  // namespace skylit::terrain::detail
