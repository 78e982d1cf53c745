-- args: --bogus
-- expect: shadenet: unknown option '--bogus' \(valid: --window, --watch, --size, --help, --version, --gl-info\)
-- expect: usage: shadenet
print("never runs")
