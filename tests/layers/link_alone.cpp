// The link-alone check: linked with one library's every object (whole archive) and nothing but
// the libraries it declares, this program links only if the library names all it depends on.
int main() { return 0; }
