#!/usr/bin/env bash
echo "C harness: not yet written"
