// The program of every link_check_<library> (cmake/cadnurbs_library.cmake): it does nothing; linking it
// with the whole library and the library's declared dependencies alone is the check.
int main() { return 0; }
