// Under AddressSanitizer only: dlclose() does nothing, so the Vulkan driver and the layers the
// loader opens stay mapped until the process exits and LeakSanitizer can name them in its report.
// The loader closes them at vkDestroyInstance, and the frames of an unloaded module read
// "<unknown module>", which no suppression can match (tests/sanitizers/lsan.supp). The definition
// in the executable takes the place of libc's for every library; weak, so any number of
// translation units may include this.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
extern "C" [[gnu::weak]] int dlclose(void*) { return 0; }
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
extern "C" [[gnu::weak]] int dlclose(void*) { return 0; }
#endif
#endif
