/* Calls one function of the deprecated group: check_deprecated.sh compiles it to see the compiler warn. */
#include <octocap/octocap.h>

int main(void) {
  octocap_frame_info_t info;
  return (int)octocap_session_get_frame_info(NULL, &info);
}
