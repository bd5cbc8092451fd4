#!/usr/bin/env bash
echo "fuzzer: not yet written"
