#pragma once
// Mouse camera control on a scene camera, and the camera's line in .sce syntax.
#include <string>

#include "meshtrace/geometry/camera.h"

namespace meshtrace::viewer {

// Turns the eye around the centre: dx pixels of drag yaw about the up
// vector, dy pixels pitch about the image's horizontal axis (stopping short
// of the poles). 0.5 degree per pixel.
CameraSpec orbit(const CameraSpec& camera, double dxPixels, double dyPixels);

// Moves eye and centre together so that the point under the mouse in the
// centre's plane follows the mouse (image pixels, y up).
CameraSpec pan(const CameraSpec& camera, double dxPixels, double dyPixels);

// Moves the eye toward the centre (steps > 0) or away, 10% of the distance a step.
CameraSpec zoom(const CameraSpec& camera, double steps);

// The same camera in every field.
bool sameCamera(const CameraSpec& a, const CameraSpec& b);

// "camera ex ey ez cx cy cz ux uy uz fovy width height", shortest round-trip numbers.
std::string cameraLine(const CameraSpec& camera);
// The camera of such a line (pasted: surrounding blanks and a trailing
// comment allowed), read by the scene reader. Throws what it throws for a
// bad line (InputError, naming "pasted" and the problem).
CameraSpec parseCameraLine(const std::string& line);

}  // namespace meshtrace::viewer
