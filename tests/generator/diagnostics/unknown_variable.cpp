// A pragma naming a variable that does not exist.
int altitude;

#pragma symcr checkpoint(altitude, altitud)
