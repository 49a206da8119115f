"""The grader's parts: what a submission may provide, what it must not contain, the sandbox
that builds and runs it, the evidence a verdict needs, and the reports."""
