// Placeholder until the AprilTag detector lands.
namespace roiclip::apriltag {}
