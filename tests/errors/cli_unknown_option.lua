-- args: --bogus
-- expect: shadenet: unknown option '--bogus' \(valid: --window, --watch, --size, --help, --version\)
-- expect: usage: shadenet
print("never runs")
