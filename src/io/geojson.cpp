// Placeholder until the GeoJSON reader lands.
namespace roiclip::io {}
