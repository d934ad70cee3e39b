// Placeholder until the OpenCV conversions land.
namespace roiclip::opencv {}
