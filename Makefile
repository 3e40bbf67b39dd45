# Convenience targets for developers; the README's two commands work without make.
.PHONY: run test
run:
	bash scripts/run.sh
test:
	bash scripts/test.sh
