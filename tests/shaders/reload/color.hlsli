#define RELOAD_COLOR float3(0.25, 0.5, 0.75)
