// Copy to secrets.h (which git ignores) and fill in for each wristband.
#pragma once

#define ALPLAN_WIFI_SSID "home-network"
#define ALPLAN_WIFI_PASSWORD "password"
// 1-32 characters of [A-Za-z0-9._-]; the service knows the device by it.
#define ALPLAN_DEVICE_ID "wb-01"
// The device's bearer token, issued by the service for this device id.
#define ALPLAN_DEVICE_TOKEN "replace-with-the-device-token"
// The service's readings endpoint.
#define ALPLAN_READINGS_URL "https://alplan.example.org/v1/readings"
// The PEM certificate of the CA that signed the service's TLS certificate.
#define ALPLAN_SERVICE_CA_PEM \
  "-----BEGIN CERTIFICATE-----\n" \
  "...\n" \
  "-----END CERTIFICATE-----\n"
