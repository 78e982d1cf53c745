-- args: --bogus
-- expect: shadenet: unknown option '--bogus' \(valid: --window, --size, --help, --version\)
-- expect: usage: shadenet
print("never runs")
