# Convenience targets for developers; the README's two commands work without make.
.PHONY: run test sanitize
run:
	bash scripts/run.sh
test:
	bash scripts/test.sh
sanitize:
	bash scripts/sanitize.sh
