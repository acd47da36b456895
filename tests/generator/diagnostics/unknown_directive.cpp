// A misspelt directive.
int altitude;
#pragma symcr checkpiont(altitude)
